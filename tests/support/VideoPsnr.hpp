#pragma once
// PSNR of a decoded frame against the frame that was sent, measured as
// video encoders and FFmpeg's psnr filter report it: over the Y, U and V
// planes of 4:2:0 (their pixels together). Measured on BGR instead, the
// halved colour resolution of every H.264 stream alone costs a composite
// with sharp CG edges about 36 dB, whatever the bitrate; on YUV 4:2:0 the
// figure is the encoder's and the network's.
//
//   EXPECT_GE(test::videoPsnr(decoded, sent), 35.0);

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace arcomp::test {

inline double videoPsnr(const cv::Mat& bgrA, const cv::Mat& bgrB) {
    cv::Mat a, b;
    cv::cvtColor(bgrA, a, cv::COLOR_BGR2YUV_I420);
    cv::cvtColor(bgrB, b, cv::COLOR_BGR2YUV_I420);
    return cv::PSNR(a, b);
}

}  // namespace arcomp::test
