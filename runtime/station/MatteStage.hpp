#pragma once
// The person layer of the current video frame: the matte's output,
// premultiplied BGRA at the video's size. A live frame that did not change
// keeps the last layer rather than matting the same image again.
// Two layers are written in turn, so that the one person() gave stays
// untouched while the next frame is matted (a pipelined station composites
// frame N while the matte of frame N+1 runs on another thread).
//
//   MatteStage matte(spec);                          // throws what makeMatte throws
//   matte.run(capture.image(), capture.newFrame());
//   compositor.person(matte.person());

#include "video/matte/MatteSpec.hpp"

#include <opencv2/core/mat.hpp>

#include <array>
#include <memory>

namespace arcomp {

class MatteStage {
public:
    explicit MatteStage(const MatteSpec& spec) : matte_(makeMatte(spec)) {}

    void run(const cv::Mat& frame, bool newFrame) {
        if (!newFrame && !person().empty()) return;
        current_ ^= 1U;
        matte_->apply(frame, layers_[current_]);
    }
    const cv::Mat& person() const { return layers_[current_]; }

private:
    std::unique_ptr<PersonMatte> matte_;
    std::array<cv::Mat, 2> layers_;
    unsigned current_ = 0;
};

}  // namespace arcomp
