#pragma once
// The frame at a matte's model scale: what cv::resize with INTER_AREA gives,
// byte for byte. OpenCV 4.6 averages each 4x4 block of a BGR frame one
// sample at a time (only the factor of 2 has vectors), 1.8 ms of a 1080p
// frame at the quarter scale that a 1080p station mattes at; here a factor
// of 4 on CV_8UC3 with both sides divisible by 4 runs in vectors, anything
// else goes to cv::resize.
//
//   shrinkByArea(frame, 0.25, small);   // small: 480x270 for a 1920x1080 frame

#include <opencv2/core/mat.hpp>

namespace arcomp {

void shrinkByArea(const cv::Mat& frame, double scale, cv::Mat& small);

}  // namespace arcomp
