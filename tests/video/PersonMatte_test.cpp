// premultiply, the last step of every matte: each byte is v * alpha / 255
// rounded to nearest, and where alpha is 0 the layer is 0 whatever the
// reused buffer held before.
#include "video/matte/PersonMatte.hpp"

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

using namespace arcomp;

namespace {

std::uint8_t expected(int v, int k) { return static_cast<std::uint8_t>((v * k + 127) / 255); }

// Every pixel of `person` against the rounded product, and alpha carried over.
void expectPremultiplied(const cv::Mat& frame, const cv::Mat& alpha, const cv::Mat& person) {
    ASSERT_EQ(person.type(), CV_8UC4);
    ASSERT_EQ(person.size(), frame.size());
    int wrong = 0;
    for (int y = 0; y < frame.rows; ++y)
        for (int x = 0; x < frame.cols; ++x) {
            const cv::Vec3b c = frame.at<cv::Vec3b>(y, x);
            const int k = alpha.at<std::uint8_t>(y, x);
            const cv::Vec4b want(expected(c[0], k), expected(c[1], k), expected(c[2], k), static_cast<std::uint8_t>(k));
            if (person.at<cv::Vec4b>(y, x) != want && wrong++ < 5)
                ADD_FAILURE() << "at (" << x << ", " << y << "): " << person.at<cv::Vec4b>(y, x) << ", expected "
                              << want;
        }
    EXPECT_EQ(wrong, 0);
}

}  // namespace

TEST(PersonMatte, premultiplyRoundsEveryColourAndAlphaPairToNearest) {
    // Column = colour level, row = alpha: all 65,536 pairs, three columns
    // past a whole number of vectors so that the row's tail is covered too.
    cv::Mat frame(256, 259, CV_8UC3), alpha(256, 259, CV_8UC1);
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 259; ++x) {
            const auto v = static_cast<std::uint8_t>(x % 256);
            frame.at<cv::Vec3b>(y, x) =
                cv::Vec3b(v, static_cast<std::uint8_t>(255 - v), static_cast<std::uint8_t>(x * 7));
            alpha.at<std::uint8_t>(y, x) = static_cast<std::uint8_t>(y);
        }
    cv::Mat person;
    premultiply(frame, alpha, person);
    expectPremultiplied(frame, alpha, person);
}

TEST(PersonMatte, premultiplyClearsWhereAlphaIsZeroInAReusedBuffer) {
    cv::RNG rng(23);
    for (const int width : {1, 7, 15, 16, 17, 33, 64, 101}) {
        cv::Mat frame(9, width, CV_8UC3), alpha(9, width, CV_8UC1, cv::Scalar(0));
        rng.fill(frame, cv::RNG::UNIFORM, 0, 256);
        // Row 0 stays empty; then alpha at the first column, at the last,
        // at both ends only, at one inner column, and random spans with holes.
        alpha.at<std::uint8_t>(1, 0) = 200;
        alpha.at<std::uint8_t>(2, width - 1) = 9;
        alpha.at<std::uint8_t>(3, 0) = alpha.at<std::uint8_t>(3, width - 1) = 255;
        alpha.at<std::uint8_t>(4, width / 2) = 128;
        for (int y = 5; y < 9; ++y) {
            const int from = rng.uniform(0, width), to = rng.uniform(from, width) + 1;
            for (int x = from; x < to; ++x)
                alpha.at<std::uint8_t>(y, x) =
                    static_cast<std::uint8_t>(rng.uniform(0, 3) == 0 ? 0 : rng.uniform(1, 256));
        }
        cv::Mat person(9, width, CV_8UC4, cv::Scalar(77, 77, 77, 77));  // what the last frame left
        const std::uint8_t* buffer = person.data;
        premultiply(frame, alpha, person);
        EXPECT_EQ(person.data, buffer) << "the buffer is reused";
        SCOPED_TRACE("width " + std::to_string(width));
        expectPremultiplied(frame, alpha, person);
    }
}
