#pragma once
// Structural similarity of two images, as Wang, Bovik, Sheikh and
// Simoncelli define it ("Image quality assessment: from error visibility
// to structural similarity", IEEE Trans. Image Processing 13(4), 2004):
// the local SSIM index of eq. 13 with their constants (K1 = 0.01,
// K2 = 0.03, L = 255), local statistics under an 11x11 circular Gaussian
// window with sigma 1.5, averaged over the image (mean SSIM, eq. 17).
// As in their reference code, only windows wholly inside the image count
// (a 5-pixel border is left out). Colour images are compared channel by
// channel on their 8-bit (sRGB-encoded) values and the channels' means
// averaged, so a wrong hue costs as much as a wrong brightness.
//
//   double s = ssim(cv::imread("a.png"), cv::imread("b.png"));  // 1: identical
//   double o = ssim(a, b, objectMask);                          // over the object only

#include <opencv2/core.hpp>

namespace arcomp {

// `a` and `b`: 8-bit, the same size (at least 11x11) and channel count.
// With a `mask` (8-bit, one channel, same size) the local index is averaged
// over its non-zero pixels only: where a small object would otherwise be
// outweighed by a background that matches trivially. Throws
// std::invalid_argument for images that do not match, or a mask with no
// pixel inside the border.
double ssim(const cv::Mat& a, const cv::Mat& b, const cv::Mat& mask = cv::Mat());

}  // namespace arcomp
