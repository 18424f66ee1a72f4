// shrinkByArea gives cv::resize's INTER_AREA bytes: on random frames, on
// blocks whose mean lies exactly half-way between two levels, at widths
// shorter than a vector and with a scalar tail, and at sizes the vector
// path does not take.
#include "video/pixels/AreaShrink.hpp"

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

using namespace arcomp;

namespace {

void expectSameAsOpenCv(const cv::Mat& frame, double scale) {
    cv::Mat expected, small;
    cv::resize(frame, expected, {}, scale, scale, cv::INTER_AREA);
    shrinkByArea(frame, scale, small);
    ASSERT_EQ(small.size(), expected.size());
    ASSERT_EQ(small.type(), expected.type());
    EXPECT_EQ(cv::countNonZero(cv::Mat(small != expected).reshape(1)), 0)
        << frame.cols << "x" << frame.rows << " at " << scale;
}

}  // namespace

TEST(AreaShrink, quarterScaleMatchesOpenCvOnRandomFrames) {
    cv::RNG rng(4);
    for (const cv::Size size : {cv::Size(1920, 1080), cv::Size(4, 4), cv::Size(8, 12), cv::Size(20, 8),
                                cv::Size(44, 16), cv::Size(100, 28)}) {
        cv::Mat frame(size, CV_8UC3);
        rng.fill(frame, cv::RNG::UNIFORM, 0, 256);
        expectSameAsOpenCv(frame, 0.25);
    }
}

TEST(AreaShrink, halfWayMeansRoundToEvenAsOpenCvDoes) {
    // One pixel of each 4x4 block holds 16 q + 8, the rest 0: the block's
    // mean is q + 1/2, which rounds to the even one of q and q + 1.
    cv::Mat frame(16, 64, CV_8UC3, cv::Scalar(0, 0, 0));
    for (int by = 0; by < 4; ++by)
        for (int bx = 0; bx < 16; ++bx)
            for (int c = 0; c < 3; ++c)
                frame.at<cv::Vec3b>(4 * by + c, 4 * bx + by)[c] =
                    static_cast<std::uint8_t>(16 * ((bx + by + c) % 16) + 8);
    cv::Mat small;
    shrinkByArea(frame, 0.25, small);
    for (int by = 0; by < 4; ++by)
        for (int bx = 0; bx < 16; ++bx)
            for (int c = 0; c < 3; ++c) {
                const int q = (bx + by + c) % 16;
                EXPECT_EQ(small.at<cv::Vec3b>(by, bx)[c], q + (q & 1))
                    << "block " << bx << ", " << by << " channel " << c;
            }
    expectSameAsOpenCv(frame, 0.25);
}

TEST(AreaShrink, otherScalesAndSizesAreOpenCvs) {
    cv::RNG rng(5);
    cv::Mat odd(30, 42, CV_8UC3), grey(40, 40, CV_8UC1);
    rng.fill(odd, cv::RNG::UNIFORM, 0, 256);
    rng.fill(grey, cv::RNG::UNIFORM, 0, 256);
    expectSameAsOpenCv(odd, 0.25);
    expectSameAsOpenCv(odd, 0.5);
    expectSameAsOpenCv(grey, 0.25);
}
