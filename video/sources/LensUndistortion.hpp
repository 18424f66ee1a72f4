#pragma once
// Takes the lens's distortion out of each video frame, so that the video
// matches the pinhole camera the CG is drawn with. The remap tables are
// computed once; each frame then costs one cv::remap. The undistorted
// image keeps the same camera matrix, so the calibrated intrinsics stay
// valid for the CG.
//
//   LensUndistortion lens(cameraMatrix, {k1, k2, p1, p2, k3}, frame.size());
//   lens.apply(frame);   // frame now holds a new, undistorted image

#include <opencv2/core.hpp>

namespace arcomp {

class LensUndistortion {
public:
    // cameraMatrix and distortion for frames of exactly `size`.
    LensUndistortion(const cv::Matx33d& cameraMatrix, const cv::Vec<double, 5>& distortion, cv::Size size);

    // A frame of another size than the one given is an error
    // (std::invalid_argument): the tables hold for one size only.
    void apply(cv::Mat& frame);

private:
    cv::Mat mapX_, mapY_;  // fixed-point tables (CV_16SC2 and CV_16UC1): faster remaps than float
};

}  // namespace arcomp
