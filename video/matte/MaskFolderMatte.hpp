#pragma once
// A matte made elsewhere: one mask image per frame, read from a folder in
// the names a station's `output.matte_dir` writes (matte-000000.png, ...),
// frame after frame from the first. For replaying a review with the masks
// an external segmenter (or a person, by hand) produced, and for measuring
// the rest of the pipeline against ground-truth masks.
//
//   MaskFolderMatte matte({.folder = "review/masks"});
//   matte.apply(frame, person);   // frame 0 takes matte-000000.png
//
// A mask is 8-bit grey, its value the alpha; a colour mask counts its first
// channel. A missing or unreadable mask, or one of another size, is a
// VideoError naming the file: the masks and the video do not belong together.

#include "video/matte/PersonMatte.hpp"

#include <cstdint>
#include <filesystem>

namespace arcomp {

struct MaskFolderSpec {
    std::filesystem::path folder;
};

class MaskFolderMatte final : public PersonMatte {
public:
    explicit MaskFolderMatte(MaskFolderSpec spec) : spec_(std::move(spec)) {}
    void apply(const cv::Mat& frame, cv::Mat& person) override;
    std::string name() const override { return "masks " + spec_.folder.string(); }

    static std::filesystem::path maskFile(const std::filesystem::path& folder, std::uint64_t frame);

private:
    MaskFolderSpec spec_;
    std::uint64_t next_ = 0;
    cv::Mat alpha_;
};

}  // namespace arcomp
