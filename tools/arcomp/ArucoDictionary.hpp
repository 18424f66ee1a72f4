#pragma once
// ArUco dictionaries by the names OpenCV gives them, for the calibrate
// commands' --dictionary:
//
//   cv::Ptr<cv::aruco::Dictionary> d = arucoDictionary("DICT_4X4_50");   // InputError for an unknown name

#include <opencv2/aruco.hpp>

#include <string>

namespace arcomp {

cv::Ptr<cv::aruco::Dictionary> arucoDictionary(const std::string& name);

}  // namespace arcomp
