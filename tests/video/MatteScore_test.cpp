#include "tools/bench/report/MatteScore.hpp"

#include <gtest/gtest.h>

namespace arcomp {
namespace {

// One row of labels: every CDnet value once, under a mask that says "person" everywhere.
TEST(MatteScore, countsTheCdnetWay) {
    const cv::Mat labels = (cv::Mat_<std::uint8_t>(1, 5) << 0, 50, 85, 170, 255);
    MatteScore all;
    all.add(cv::Mat(1, 5, CV_8UC1, cv::Scalar(255)), labels);
    EXPECT_EQ(all.truePositives, 1);   // 255: the person
    EXPECT_EQ(all.falsePositives, 2);  // 0 and 50 (hard shadow) are background
    EXPECT_EQ(all.falseNegatives, 0);
    EXPECT_EQ(all.trueNegatives, 0);  // 85 and 170 are not counted at all

    MatteScore none;
    none.add(cv::Mat::zeros(1, 5, CV_8UC1), labels);
    EXPECT_EQ(none.falseNegatives, 1);
    EXPECT_EQ(none.trueNegatives, 2);
    EXPECT_EQ(none.truePositives + none.falsePositives, 0);
}

TEST(MatteScore, pixelsOutsideTheRegionOfInterestAreNotCounted) {
    const cv::Mat labels = (cv::Mat_<std::uint8_t>(1, 4) << 255, 255, 0, 0);
    const cv::Mat roi = (cv::Mat_<std::uint8_t>(1, 4) << 255, 0, 255, 0);
    MatteScore s;
    s.add(cv::Mat(1, 4, CV_8UC1, cv::Scalar(255)), labels, roi);
    EXPECT_EQ(s.truePositives, 1);
    EXPECT_EQ(s.falsePositives, 1);
}

TEST(MatteScore, figuresFollowFromTheTotals) {
    MatteScore s{.truePositives = 60, .falsePositives = 20, .falseNegatives = 40, .trueNegatives = 880};
    EXPECT_DOUBLE_EQ(s.precision(), 0.75);
    EXPECT_DOUBLE_EQ(s.recall(), 0.6);
    EXPECT_DOUBLE_EQ(s.fMeasure(), 2 * 0.75 * 0.6 / 1.35);
    EXPECT_DOUBLE_EQ(s.iou(), 0.5);
    EXPECT_DOUBLE_EQ(s.percentWrong(), 6.0);
    s += s;
    EXPECT_EQ(s.truePositives, 120);
    EXPECT_DOUBLE_EQ(s.fMeasure(), 2 * 0.75 * 0.6 / 1.35);
    EXPECT_DOUBLE_EQ(MatteScore{}.fMeasure(), 0.0);  // nothing counted: no division by zero
}

TEST(MatteScore, maskThresholdIsHalfway) {
    const cv::Mat labels = (cv::Mat_<std::uint8_t>(1, 2) << 255, 255);
    const cv::Mat mask = (cv::Mat_<std::uint8_t>(1, 2) << 127, 128);
    MatteScore s;
    s.add(mask, labels);
    EXPECT_EQ(s.truePositives, 1);
    EXPECT_EQ(s.falseNegatives, 1);
}

}  // namespace
}  // namespace arcomp
