#include "tests/support/MaskOverlap.hpp"
#include "video/matte/ChromaKeyMatte.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include <random>

namespace arcomp {
namespace {

// A studio frame: a green backing with uneven light and sensor noise, and a
// person-like shape (skin-toned head, dark-blue body) whose mask is known.
struct StudioFrame {
    cv::Mat image, truth;
};

StudioFrame studioFrame(int w, int h) {
    StudioFrame f;
    f.image.create(h, w, CV_8UC3);
    std::mt19937 rng(7);
    std::normal_distribution<float> noise(0.0f, 3.0f);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            // Light falls off towards the corners: luma changes, chroma barely.
            const float light = 0.75f + 0.25f * std::cos(3.0f * (static_cast<float>(x) / static_cast<float>(w) - 0.5f));
            f.image.at<cv::Vec3b>(y, x) = cv::Vec3b(cv::saturate_cast<uchar>(40 * light + noise(rng)),
                                                    cv::saturate_cast<uchar>(180 * light + noise(rng)),
                                                    cv::saturate_cast<uchar>(30 * light + noise(rng)));
        }
    f.truth = cv::Mat::zeros(h, w, CV_8UC1);
    const cv::Point head(w / 2, h / 4);
    const cv::Rect body(w / 2 - w / 8, h / 4 + h / 10, w / 4, h / 2);
    cv::circle(f.truth, head, h / 10, 255, cv::FILLED);
    cv::rectangle(f.truth, body, 255, cv::FILLED);
    f.image.setTo(cv::Scalar(40, 30, 140), f.truth);  // skin-ish everywhere first
    cv::Mat bodyMask = cv::Mat::zeros(h, w, CV_8UC1);
    cv::rectangle(bodyMask, body, 255, cv::FILLED);
    f.image.setTo(cv::Scalar(120, 50, 30), bodyMask);
    return f;
}

TEST(ChromaKeyMatte, knownShapeHasIouAtLeast098) {
    const StudioFrame f = studioFrame(640, 480);
    ChromaKeyMatte key({.keyBgr = {40, 180, 30}, .similarity = 0.08f, .smoothness = 0.06f, .spill = 0.1f});
    cv::Mat person;
    key.apply(f.image, person);
    ASSERT_EQ(person.type(), CV_8UC4);
    cv::Mat opaque;
    cv::threshold(alphaOf(person), opaque, 127, 255, cv::THRESH_BINARY);
    EXPECT_GE(arcomp::test::maskIou(opaque, f.truth), 0.98);
}

TEST(ChromaKeyMatte, keyedOutPixelsArePremultipliedToZero) {
    const StudioFrame f = studioFrame(160, 120);
    ChromaKeyMatte key({.keyBgr = {40, 180, 30}});
    cv::Mat person;
    key.apply(f.image, person);
    const cv::Vec4b corner = person.at<cv::Vec4b>(2, 2);
    EXPECT_EQ(corner, cv::Vec4b(0, 0, 0, 0));
    const cv::Vec4b body = person.at<cv::Vec4b>(60, 80);
    EXPECT_EQ(body[3], 255);
    EXPECT_EQ(body[0], 120);  // far from the key: colour untouched
}

TEST(ChromaKeyMatte, spillIsDesaturatedNearTheKey) {
    // A greenish-grey pixel just outside the keyed range keeps its alpha but
    // loses most of its green cast when spill removal is on.
    cv::Mat frame(1, 1, CV_8UC3, cv::Scalar(110, 150, 100));
    const cv::Vec2f key = cbcrOf({40, 180, 30});
    const cv::Vec2f px = cbcrOf({110, 150, 100});
    const float d = std::hypot(px[0] - key[0], px[1] - key[1]);
    ChromaKeySpec spec{.keyBgr = {40, 180, 30}, .similarity = d - 0.2f, .smoothness = 0.01f, .spill = 0.0f};
    cv::Mat plain, despilled;
    ChromaKeyMatte(spec).apply(frame, plain);
    spec.spill = 0.6f;
    ChromaKeyMatte(spec).apply(frame, despilled);
    EXPECT_EQ(plain.at<cv::Vec4b>(0, 0)[3], 255);
    EXPECT_EQ(despilled.at<cv::Vec4b>(0, 0)[3], 255);
    const auto cast = [](cv::Vec4b p) { return p[1] - (p[0] + p[2]) / 2; };
    EXPECT_EQ(cast(plain.at<cv::Vec4b>(0, 0)), 150 - 105);
    EXPECT_LT(cast(despilled.at<cv::Vec4b>(0, 0)), 20);
}

TEST(ChromaKeyMatte, alphaRampIsSmoothBetweenSimilarityAndSmoothness) {
    EXPECT_EQ(chromaKeyAlpha(0.05f, 0.1f, 0.1f), 0.0f);
    EXPECT_FLOAT_EQ(chromaKeyAlpha(0.15f, 0.1f, 0.1f), 0.5f);
    EXPECT_EQ(chromaKeyAlpha(0.25f, 0.1f, 0.1f), 1.0f);
}

}  // namespace
}  // namespace arcomp
