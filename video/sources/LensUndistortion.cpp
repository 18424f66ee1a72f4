#include "video/sources/LensUndistortion.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include <stdexcept>

namespace arcomp {

LensUndistortion::LensUndistortion(const cv::Matx33d& cameraMatrix, const cv::Vec<double, 5>& distortion,
                                   cv::Size size) {
    cv::initUndistortRectifyMap(cameraMatrix, distortion, cv::noArray(), cameraMatrix, size, CV_16SC2, mapX_, mapY_);
}

void LensUndistortion::apply(cv::Mat& frame) {
    if (frame.size() != mapX_.size())
        throw std::invalid_argument("lens undistortion: a " + std::to_string(frame.cols) + "x" +
                                    std::to_string(frame.rows) + " frame, but the tables are for " +
                                    std::to_string(mapX_.cols) + "x" + std::to_string(mapX_.rows));
    // A new image each frame: the old one may still be shared with the
    // source's buffers or a stage that kept it.
    cv::Mat undistorted;
    cv::remap(frame, undistorted, mapX_, mapY_, cv::INTER_LINEAR, cv::BORDER_CONSTANT);
    frame = undistorted;
}

}  // namespace arcomp
