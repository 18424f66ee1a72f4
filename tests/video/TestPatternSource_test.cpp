#include "video/sources/TestPatternSource.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

using namespace arcomp;

TEST(TestPatternSource, sameFrameIndexGivesIdenticalPixels) {
    TestPatternSource a({.width = 320, .height = 240, .fps = 30, .paced = false});
    TestPatternSource b({.width = 320, .height = 240, .fps = 30, .paced = false});
    for (int i = 0; i < 3; ++i) {
        GrabResult ra = a.grab(), rb = b.grab();
        ASSERT_TRUE(ra.frame && rb.frame);
        EXPECT_EQ(ra.frame->sequence, static_cast<std::uint64_t>(i));
        EXPECT_EQ(cv::norm(ra.frame->image, rb.frame->image, cv::NORM_INF), 0.0);
    }
}

TEST(TestPatternSource, circleMovesAndFramesDiffer) {
    TestPatternSource p({.width = 640, .height = 360, .fps = 60, .paced = false});
    EXPECT_EQ(p.circleCentre(0).x, 0);
    EXPECT_EQ(p.circleCentre(60).x, 160);  // a quarter width per second
    EXPECT_GT(cv::norm(p.render(0), p.render(1), cv::NORM_L1), 0.0);
    EXPECT_EQ(p.render(60).at<cv::Vec3b>(180, 160), cv::Vec3b(40, 160, 230));
}

TEST(TestPatternSource, honoursSizeAndRate) {
    TestPatternSource p({.width = 1920, .height = 1080, .fps = 25, .paced = false});
    p.grab();
    GrabResult r = p.grab();
    ASSERT_TRUE(r.frame);
    EXPECT_EQ(r.frame->image.size(), cv::Size(1920, 1080));
    EXPECT_EQ(r.frame->timestamp, std::chrono::milliseconds(40));
}

TEST(TestPatternSource, rejectsImpossibleSizes) {
    EXPECT_ANY_THROW(TestPatternSource({.width = 0, .height = 480, .fps = 30, .paced = false}));
    EXPECT_ANY_THROW(TestPatternSource({.width = 640, .height = 480, .fps = 0, .paced = false}));
}
