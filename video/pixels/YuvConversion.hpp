#pragma once
// YUV to BGR with the matrix and range the camera actually used. Getting
// either wrong shifts skin tones and crushes or lifts blacks, which shows at
// the seam between video and CG.
//
//   cv::Mat bgr = yuyvToBgr(buffer, 1280, 720, 2560, {YuvMatrix::Bt709, YuvRange::Limited});
//
// MJPEG frames are JPEG (JFIF: BT.601, full range) and go through the JPEG
// decoder instead; defaultYuvEncoding() gives the usual convention per format.

#include "video/pixels/PixelFormat.hpp"

#include <opencv2/core/mat.hpp>

#include <cstdint>
#include <vector>

namespace arcomp {

enum class YuvMatrix { Bt601, Bt709 };
enum class YuvRange { Limited, Full };  // limited: Y 16..235, C 16..240

struct YuvEncoding {
    YuvMatrix matrix = YuvMatrix::Bt601;
    YuvRange range = YuvRange::Limited;
};

// JPEG/MJPEG: BT.601 full. Raw YUYV/NV12: limited range, BT.709 from 720
// lines up (HD), BT.601 below (SD): what UVC cameras send unless they say otherwise.
YuvEncoding defaultYuvEncoding(PixelFormat format, int height);

cv::Mat yuyvToBgr(const std::uint8_t* data, int width, int height, int stride, YuvEncoding encoding);
cv::Mat nv12ToBgr(const std::uint8_t* y, int yStride, const std::uint8_t* uv, int uvStride, int width, int height,
                  YuvEncoding encoding);

// The inverse, for fake devices and tests (chroma is averaged over each pair
// or 2x2 block). Width must be even; for NV12 the height too.
std::vector<std::uint8_t> bgrToYuyv(const cv::Mat& bgr, YuvEncoding encoding);
std::vector<std::uint8_t> bgrToNv12(const cv::Mat& bgr, YuvEncoding encoding);

}  // namespace arcomp
