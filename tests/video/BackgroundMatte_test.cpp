#include "tests/support/MaskOverlap.hpp"
#include "video/matte/BackgroundMatte.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include <random>

namespace arcomp {
namespace {

// A static textured background (blurred noise, the same every frame apart
// from mild sensor noise) with a red-brown ellipse walking across it.
class Walker {
public:
    Walker(int w, int h) : rng_(3) {
        background_.create(h, w, CV_8UC3);
        cv::randu(background_, cv::Scalar::all(40), cv::Scalar::all(220));
        cv::GaussianBlur(background_, background_, {9, 9}, 0.0);
    }
    cv::Mat frame(int index, bool withShape, cv::Mat* truth = nullptr) {
        cv::Mat f = background_.clone();
        cv::Mat n(f.size(), CV_16SC3);
        cv::randn(n, cv::Scalar::all(0), cv::Scalar::all(2));
        cv::Mat f16;
        f.convertTo(f16, CV_16SC3);
        cv::add(f16, n, f16);
        f16.convertTo(f, CV_8UC3);
        cv::Mat mask = cv::Mat::zeros(f.size(), CV_8UC1);
        if (withShape) {
            const cv::Point centre(40 + index * 12, f.rows / 2);
            cv::ellipse(mask, centre, {f.cols / 14, f.rows / 4}, 0.0, 0.0, 360.0, 255, cv::FILLED);
            f.setTo(cv::Scalar(40, 60, 170), mask);
        }
        if (truth) *truth = mask;
        return f;
    }

private:
    std::mt19937 rng_;
    cv::Mat background_;
};

class BackgroundMatteMethods : public ::testing::TestWithParam<BackgroundMethod> {};

TEST_P(BackgroundMatteMethods, movingShapeOverStaticTextureIsFound) {
    Walker walker(320, 240);
    BackgroundMatte matte({.method = GetParam(), .scale = 0.5, .featherPx = 3, .temporal = 0.0});
    cv::Mat person, truth;
    for (int i = 0; i < 40; ++i) matte.apply(walker.frame(i, false), person);  // learn the empty place
    for (int i = 0; i < 12; ++i) matte.apply(walker.frame(i, true, &truth), person);
    cv::Mat found;
    cv::threshold(alphaOf(person), found, 127, 255, cv::THRESH_BINARY);
    EXPECT_GE(arcomp::test::maskIou(found, truth), 0.85) << matte.name();
}

INSTANTIATE_TEST_SUITE_P(All, BackgroundMatteMethods,
                         ::testing::Values(BackgroundMethod::Mog2, BackgroundMethod::Knn, BackgroundMethod::Cnt,
                                           BackgroundMethod::CleanPlate));

TEST(BackgroundMatte, emptyPlaceGivesNoPerson) {
    Walker walker(320, 240);
    BackgroundMatte matte({.method = BackgroundMethod::Mog2});
    cv::Mat person;
    for (int i = 0; i < 40; ++i) matte.apply(walker.frame(i, false), person);
    EXPECT_LT(cv::countNonZero(alphaOf(person) > 127), 320 * 240 / 500);
}

TEST(BackgroundMatte, temporalSmoothingDampsAOneFrameFlash) {
    Walker walker(320, 240);
    const auto flashAlpha = [&](double temporal) {
        BackgroundMatte matte({.method = BackgroundMethod::CleanPlate, .temporal = temporal});
        cv::Mat person, truth;
        matte.apply(walker.frame(0, false), person);
        matte.apply(walker.frame(5, true, &truth), person);
        return cv::mean(alphaOf(person), truth)[0];
    };
    EXPECT_GT(flashAlpha(0.0), 240.0);
    EXPECT_LT(flashAlpha(0.6), 0.5 * 255.0);
}

TEST(BackgroundMatte, outputIsPremultiplied) {
    Walker walker(160, 120);
    BackgroundMatte matte({.method = BackgroundMethod::CleanPlate, .featherPx = 7, .temporal = 0.0});
    cv::Mat person;
    matte.apply(walker.frame(0, false), person);
    matte.apply(walker.frame(3, true), person);
    for (int y = 0; y < person.rows; ++y)
        for (int x = 0; x < person.cols; ++x) {
            const cv::Vec4b p = person.at<cv::Vec4b>(y, x);
            ASSERT_LE(std::max({p[0], p[1], p[2]}), p[3]) << x << "," << y;
        }
}

}  // namespace
}  // namespace arcomp
