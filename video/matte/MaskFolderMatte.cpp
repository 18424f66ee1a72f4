#include "video/matte/MaskFolderMatte.hpp"

#include "video/pixels/VideoError.hpp"

#include <opencv2/imgcodecs.hpp>

#include <cstdio>

namespace arcomp {

std::filesystem::path MaskFolderMatte::maskFile(const std::filesystem::path& folder, std::uint64_t frame) {
    char name[32];
    std::snprintf(name, sizeof name, "matte-%06llu.png", static_cast<unsigned long long>(frame));
    return folder / name;
}

void MaskFolderMatte::apply(const cv::Mat& frame, cv::Mat& person) {
    const std::filesystem::path file = maskFile(spec_.folder, next_++);
    cv::Mat mask = cv::imread(file.string(), cv::IMREAD_UNCHANGED);
    if (mask.empty()) throw VideoError(file.string(), "matte", "no mask for this frame, or not an image");
    if (mask.depth() != CV_8U) throw VideoError(file.string(), "matte", "expected an 8-bit mask");
    if (mask.size() != frame.size())
        throw VideoError(file.string(), "matte",
                         "mask is " + std::to_string(mask.cols) + "x" + std::to_string(mask.rows) + ", the video " +
                             std::to_string(frame.cols) + "x" + std::to_string(frame.rows));
    if (mask.channels() > 1)
        cv::extractChannel(mask, alpha_, 0);
    else
        alpha_ = mask;
    premultiply(frame, alpha_, person);
}

}  // namespace arcomp
