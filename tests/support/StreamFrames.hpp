#pragma once
// Numbered frames through a station's StreamOutputs, and the check a
// receiver's frames pass: each readable, numbers going up, each close to
// the frame sent (PSNR >= 35 dB on YUV 4:2:0).
//
//   test::sendNumberedFrames(streams, 0, 60, {320, 240});  // 25 a second, as a station sends them
//   test::expectNumberedInOrder(receiver.frames(), {320, 240});

#include "tests/support/VideoPsnr.hpp"
#include "tools/bench/scenes/NumberedFrames.hpp"
#include "video/streams/StreamOutputs.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include <chrono>
#include <thread>
#include <vector>

namespace arcomp::test {

inline void sendNumberedFrames(StreamOutputs& out, int from, int count, cv::Size size) {
    cv::Mat rgba;
    for (int i = from; i < from + count; ++i) {
        cv::cvtColor(numberedFrame(i, size), rgba, cv::COLOR_BGR2RGBA);
        out.push(rgba.data);
        std::this_thread::sleep_for(std::chrono::milliseconds(40));
    }
}

inline void expectNumberedInOrder(const std::vector<cv::Mat>& frames, cv::Size size) {
    int last = -1;
    for (const cv::Mat& f : frames) {
        const int n = frameNumberOf(f);
        ASSERT_GT(n, last) << "frame numbers go up";
        EXPECT_GE(videoPsnr(f, numberedFrame(n, size)), 35.0) << "frame " << n;
        last = n;
    }
}

}  // namespace arcomp::test
