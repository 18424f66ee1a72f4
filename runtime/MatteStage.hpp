#pragma once
// The person layer of the current video frame: the matte's output,
// premultiplied BGRA at the video's size. A live frame that did not change
// keeps the last layer rather than matting the same image again.
//
//   MatteStage matte(spec);                          // throws what makeMatte throws
//   matte.run(capture.image(), capture.newFrame());
//   compositor.person(matte.person());

#include "video/MatteSpec.hpp"

#include <opencv2/core/mat.hpp>

#include <memory>

namespace arcomp {

class MatteStage {
public:
    explicit MatteStage(const MatteSpec& spec) : matte_(makeMatte(spec)) {}

    void run(const cv::Mat& frame, bool newFrame) {
        if (newFrame || person_.empty()) matte_->apply(frame, person_);
    }
    const cv::Mat& person() const { return person_; }

private:
    std::unique_ptr<PersonMatte> matte_;
    cv::Mat person_;
};

} // namespace arcomp
