// SSIM as Wang et al. (2004) define it: 1 for identical images, lower for a
// blurred or shifted copy, and eq. 13's value where it can be worked by hand.
#include "tools/bench/report/Ssim.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include <stdexcept>

namespace arcomp {
namespace {

// A textured test image: a checker with soft gradients, in colour.
cv::Mat pattern() {
    cv::Mat3b image(96, 128);
    for (int y = 0; y < image.rows; ++y)
        for (int x = 0; x < image.cols; ++x) {
            const bool light = ((x / 8) + (y / 8)) % 2 == 0;
            image(y, x) = cv::Vec3b(static_cast<std::uint8_t>(light ? 200 : 40), static_cast<std::uint8_t>(x * 2),
                                    static_cast<std::uint8_t>(y * 2));
        }
    return image;
}

TEST(Ssim, identicalImagesScoreOne) {
    const cv::Mat a = pattern();
    EXPECT_DOUBLE_EQ(ssim(a, a.clone()), 1.0);
}

TEST(Ssim, blurredCopyScoresLower) {
    const cv::Mat a = pattern();
    cv::Mat blurred;
    cv::GaussianBlur(a, blurred, cv::Size(7, 7), 2.0);
    const double s = ssim(a, blurred);
    EXPECT_LT(s, 0.9);
    EXPECT_GT(s, 0.0);
    EXPECT_NEAR(ssim(blurred, a), s, 1e-12) << "SSIM is symmetric";
}

TEST(Ssim, shiftedCopyScoresLowerTheFurtherItMoves) {
    const cv::Mat a = pattern();
    const auto shifted = [&](int dx) {
        cv::Mat out;
        const cv::Mat m = (cv::Mat_<double>(2, 3) << 1, 0, dx, 0, 1, 0);
        cv::warpAffine(a, out, m, a.size(), cv::INTER_NEAREST, cv::BORDER_REFLECT);
        return out;
    };
    const double one = ssim(a, shifted(1)), four = ssim(a, shifted(4));
    EXPECT_LT(one, 1.0);
    EXPECT_LT(four, one);
}

// Flat images have no variance, so eq. 13 is its luminance term alone:
// (2 * 100 * 150 + C1) / (100^2 + 150^2 + C1), C1 = (0.01 * 255)^2.
TEST(Ssim, flatImagesGiveTheLuminanceTerm) {
    const cv::Mat a(32, 32, CV_8UC1, cv::Scalar(100)), b(32, 32, CV_8UC1, cv::Scalar(150));
    const double c1 = 2.55 * 2.55;
    EXPECT_NEAR(ssim(a, b), (30000.0 + c1) / (32500.0 + c1), 1e-9);
    EXPECT_NEAR(ssim(a, b), 0.923092, 1e-6);
}

TEST(Ssim, colourChannelsAreAveraged) {
    // Two channels equal, one flat 100 against flat 150.
    cv::Mat a(32, 32, CV_8UC3, cv::Scalar(10, 100, 200)), b(32, 32, CV_8UC3, cv::Scalar(10, 150, 200));
    const double c1 = 2.55 * 2.55;
    EXPECT_NEAR(ssim(a, b), (2.0 + (30000.0 + c1) / (32500.0 + c1)) / 3.0, 1e-9);
}

// The map averaged over the mask only: where the images agree, 1, however
// much they differ outside it.
TEST(Ssim, maskLimitsTheAverage) {
    const cv::Mat a = pattern();
    cv::Mat b = a.clone();
    b(cv::Rect(64, 0, 64, 96)).setTo(cv::Scalar(0, 0, 0));
    cv::Mat left(a.size(), CV_8UC1, cv::Scalar(0)), right = left.clone();
    left(cv::Rect(0, 0, 48, 96)).setTo(255);
    right(cv::Rect(80, 0, 48, 96)).setTo(255);
    EXPECT_DOUBLE_EQ(ssim(a, b, left), 1.0);
    EXPECT_LT(ssim(a, b, right), 0.2);
    const double whole = ssim(a, b);
    EXPECT_GT(whole, ssim(a, b, right));
    EXPECT_LT(whole, 1.0);
    const cv::Mat none(a.size(), CV_8UC1, cv::Scalar(0));
    EXPECT_THROW(ssim(a, b, none), std::invalid_argument);
    EXPECT_THROW(ssim(a, b, cv::Mat(a.size(), CV_8UC3, cv::Scalar::all(255))), std::invalid_argument);
}

TEST(Ssim, mismatchedImagesThrow) {
    const cv::Mat a = pattern();
    cv::Mat gray;
    cv::cvtColor(a, gray, cv::COLOR_BGR2GRAY);
    EXPECT_THROW(ssim(a, gray), std::invalid_argument);
    EXPECT_THROW(ssim(a, a(cv::Rect(0, 0, 64, 64)).clone()), std::invalid_argument);
    const cv::Mat tiny(8, 8, CV_8UC1, cv::Scalar(0));
    EXPECT_THROW(ssim(tiny, tiny), std::invalid_argument);
}

}  // namespace
}  // namespace arcomp
