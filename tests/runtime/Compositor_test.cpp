// The compositor's one pass on hand-painted layers: the person covers CG
// behind, the holdout lets CG in front show, the backdrop shows elsewhere.

#include "runtime/Compositor.hpp"
#include "runtime/GlContext.hpp"

#include <gtest/gtest.h>

using namespace arcomp;
using namespace arcomp::gl;

namespace {

cv::Vec4b at(const Image& img, int x, int y) {
    const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width) + static_cast<std::size_t>(x)) * 4;
    return {img.rgba[i], img.rgba[i + 1], img.rgba[i + 2], img.rgba[i + 3]};
}

// Paints a rectangle of a target (x, y from the top) with a premultiplied colour.
void paint(RenderTarget& t, cv::Rect r, glm::vec4 c) {
    t.bind();
    glEnable(GL_SCISSOR_TEST);
    glScissor(r.x, t.size().y - r.y - r.height, r.width, r.height);
    glClearColor(c.r, c.g, c.b, c.a);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
}

TEST(Compositor, layersPersonOverCgOverVideoExceptWhereHeldOut) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    const glm::ivec2 size{64, 48};
    Compositor c(size);
    // Video: grey; person: the left half, solid red (BGR 0,0,200).
    cv::Mat frame(size.y, size.x, CV_8UC3, cv::Scalar(90, 90, 90));
    cv::Mat person(size.y, size.x, CV_8UC4, cv::Scalar(0, 0, 0, 0));
    person(cv::Rect(0, 0, 32, 48)).setTo(cv::Scalar(0, 0, 200, 255));
    c.uploadVideo(frame, person);
    // CG: blue on the top half; holdout: the top-left quarter.
    paint(c.cgTarget(), {0, 0, 64, 48}, glm::vec4(0.0f));
    paint(c.cgTarget(), {0, 0, 64, 24}, glm::vec4(0, 0, 1, 1));
    paint(c.holdoutTarget(), {0, 0, 64, 48}, glm::vec4(0.0f));
    paint(c.holdoutTarget(), {0, 0, 32, 24}, glm::vec4(1, 1, 1, 1));
    c.composite({});
    const Image out = c.output().read();
    EXPECT_EQ(at(out, 10, 10), cv::Vec4b(0, 0, 255, 255));    // held out: the CG in front
    EXPECT_EQ(at(out, 10, 40), cv::Vec4b(200, 0, 0, 255));    // person over the video
    EXPECT_EQ(at(out, 50, 10), cv::Vec4b(0, 0, 255, 255));    // CG over the video
    EXPECT_EQ(at(out, 50, 40), cv::Vec4b(90, 90, 90, 255));   // the video alone
}

TEST(Compositor, halfTransparentPersonBlendsPremultiplied) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    const glm::ivec2 size{16, 16};
    Compositor c(size);
    cv::Mat frame(size.y, size.x, CV_8UC3, cv::Scalar(0, 0, 0));
    cv::Mat person(size.y, size.x, CV_8UC4, cv::Scalar(0, 100, 0, 128));  // green at half alpha, premultiplied
    c.uploadVideo(frame, person);
    paint(c.cgTarget(), {0, 0, 16, 16}, glm::vec4(0, 0, 1, 1));
    paint(c.holdoutTarget(), {0, 0, 16, 16}, glm::vec4(0.0f));
    c.composite({});
    const cv::Vec4b p = at(c.output().read(), 8, 8);
    EXPECT_EQ(p[1], 100);
    EXPECT_NEAR(p[2], 127, 1);  // blue * (1 - 128/255)
    EXPECT_EQ(p[3], 255);
}

TEST(Compositor, colourBackdropReplacesTheVideo) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    const glm::ivec2 size{16, 16};
    Compositor c(size);
    cv::Mat frame(size.y, size.x, CV_8UC3, cv::Scalar(0, 255, 0));  // a green backing
    cv::Mat person(size.y, size.x, CV_8UC4, cv::Scalar(0, 0, 0, 0));
    c.uploadVideo(frame, person);
    paint(c.cgTarget(), {0, 0, 16, 16}, glm::vec4(0.0f));
    paint(c.holdoutTarget(), {0, 0, 16, 16}, glm::vec4(0.0f));
    c.composite({.backdropVideo = false, .backdropColor = {0.2f, 0.2f, 0.2f, 1.0f}});
    EXPECT_EQ(at(c.output().read(), 3, 3), cv::Vec4b(51, 51, 51, 255));
}

} // namespace
