// The compositor's layers on hand-painted inputs: the person covers CG
// behind, the holdout lets CG in front show, the backdrop shows elsewhere.

#include "runtime/composite/Compositor.hpp"
#include "runtime/gl/GlContext.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

using namespace arcomp;
using namespace arcomp::gl;

namespace {

cv::Vec4b rgbaAt(const Image& img, int x, int y) {
    const std::size_t i =
        (static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width) + static_cast<std::size_t>(x)) * 4;
    return {img.rgba[i], img.rgba[i + 1], img.rgba[i + 2], img.rgba[i + 3]};
}

// Clears a rectangle (x, y from the top) of the bound target's colour, or
// its depth: stands in for drawing CG or a holdout mesh there.
void paint(glm::ivec2 size, cv::Rect r, glm::vec4 colour) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(r.x, size.y - r.y - r.height, r.width, r.height);
    glClearColor(colour.r, colour.g, colour.b, colour.a);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
}

const glm::mat4 kProjection = glm::perspective(1.0f, 4.0f / 3.0f, 0.5f, 100.0f);

// A holdout `metres` along the view axis over the rectangle.
void holdOut(glm::ivec2 size, cv::Rect r, float metres) {
    const glm::vec4 clip = kProjection * glm::vec4(0.0f, 0.0f, -metres, 1.0f);
    glEnable(GL_SCISSOR_TEST);
    glScissor(r.x, size.y - r.y - r.height, r.width, r.height);
    glClearDepthf(0.5f * clip.z / clip.w + 0.5f);
    glClear(GL_DEPTH_BUFFER_BIT);
    glClearDepthf(1.0f);
    glDisable(GL_SCISSOR_TEST);
}

// Everyone on one plane, 5 m away.
PersonDepths onePlane(float metres = 5.0f) { return PersonDepths::everyoneAt(metres); }

class CompositorOnEachApi : public ::testing::TestWithParam<GlRequest> {};

TEST_P(CompositorOnEachApi, layersPersonOverCgOverVideoExceptWhereHeldOut) {
    auto ctx = HeadlessContext::create(GetParam());
    const glm::ivec2 size{128, 96};
    Compositor c(size);
    cv::Mat frame(size.y, size.x, CV_8UC3, cv::Scalar(90, 90, 90));  // grey video
    cv::Mat person(size.y, size.x, CV_8UC4, cv::Scalar(0, 0, 0, 0));
    person(cv::Rect(0, 0, 64, 96)).setTo(cv::Scalar(0, 0, 200, 255));  // solid red person, left half
    c.begin(frame, {});
    paint(size, {0, 0, 128, 48}, glm::vec4(0, 0, 1, 1));  // blue CG, top half
    c.beginHoldout();
    holdOut(size, {0, 0, 64, 48}, 3.0f);  // the CG top-left is in front of the person
    c.endHoldout();
    c.person(person, onePlane(), kProjection);
    const Image out = c.output().read();
    EXPECT_EQ(rgbaAt(out, 10, 10), cv::Vec4b(0, 0, 255, 255));    // held out: the CG in front
    EXPECT_EQ(rgbaAt(out, 10, 80), cv::Vec4b(200, 0, 0, 255));    // person over the video
    EXPECT_EQ(rgbaAt(out, 100, 10), cv::Vec4b(0, 0, 255, 255));   // CG over the video
    EXPECT_EQ(rgbaAt(out, 100, 80), cv::Vec4b(90, 90, 90, 255));  // the video alone
    EXPECT_EQ(c.personTiles(), 8u * 12u);                         // 64x96 of 8-pixel tiles
}

// Two people in slots of their own, on a slot image at half size, and a
// stray matte pixel in no slot: each is cut only by a holdout nearer than
// themselves.
TEST_P(CompositorOnEachApi, eachPersonIsCutOnlyByHoldoutsNearerThanThem) {
    auto ctx = HeadlessContext::create(GetParam());
    const glm::ivec2 size{128, 96};
    Compositor c(size);
    cv::Mat frame(size.y, size.x, CV_8UC3, cv::Scalar(90, 90, 90));
    cv::Mat person(size.y, size.x, CV_8UC4, cv::Scalar(0, 0, 0, 0));
    person(cv::Rect(0, 0, 40, 96)).setTo(cv::Scalar(0, 0, 200, 255));   // near, left
    person(cv::Rect(80, 0, 48, 96)).setTo(cv::Scalar(0, 200, 0, 255));  // far, right
    person(cv::Rect(50, 90, 4, 4)).setTo(cv::Scalar(200, 0, 0, 255));   // untracked, on the plane
    PersonDepths depths = onePlane(20.0f);
    depths.slotScale = 2;
    depths.slots = cv::Mat(48, 64, CV_8UC1, cv::Scalar(0));
    depths.slots(cv::Rect(0, 0, 20, 48)).setTo(1);
    depths.slots(cv::Rect(40, 0, 24, 48)).setTo(2);
    depths.people = 2;
    depths.setFlat(1, 3.0f);
    depths.setFlat(2, 9.0f);
    EXPECT_FLOAT_EQ(depths.farthest(), 20.0f);
    c.begin(frame, {});
    paint(size, {0, 0, 128, 48}, glm::vec4(0, 0, 1, 1));  // blue CG across the top
    c.beginHoldout();
    holdOut(size, {0, 0, 128, 48}, 6.0f);    // 6 m away: behind the left person, in front of the right one
    holdOut(size, {0, 48, 128, 48}, 15.0f);  // the bottom: 15 m, behind both, in front of the plane
    c.endHoldout();
    c.person(person, depths, kProjection);
    const Image out = c.output().read();
    EXPECT_EQ(rgbaAt(out, 10, 10), cv::Vec4b(200, 0, 0, 255));   // near person over the CG
    EXPECT_EQ(rgbaAt(out, 100, 10), cv::Vec4b(0, 0, 255, 255));  // far person behind it
    EXPECT_EQ(rgbaAt(out, 10, 80), cv::Vec4b(200, 0, 0, 255));
    EXPECT_EQ(rgbaAt(out, 100, 80), cv::Vec4b(0, 200, 0, 255));
    EXPECT_EQ(rgbaAt(out, 51, 91), cv::Vec4b(90, 90, 90, 255));  // the plane's pixel is behind the 15 m holdout
}

INSTANTIATE_TEST_SUITE_P(Gl, CompositorOnEachApi, ::testing::Values(GlRequest::Gl33, GlRequest::Es3),
                         [](const auto& info) { return info.param == GlRequest::Gl33 ? "gl33" : "es3"; });

TEST(Compositor, personCoversCgBehindWhereNotHeldOut) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    const glm::ivec2 size{40, 40};
    Compositor c(size);
    cv::Mat frame(size.y, size.x, CV_8UC3, cv::Scalar(0, 0, 0));
    cv::Mat person(size.y, size.x, CV_8UC4, cv::Scalar(0, 0, 0, 0));
    person.at<cv::Vec4b>(5, 37) = cv::Vec4b(10, 20, 30, 255);  // one pixel, top right
    c.begin(frame, {});
    paint(size, {0, 0, 40, 40}, glm::vec4(0, 1, 0, 1));
    c.beginHoldout();
    c.endHoldout();
    c.person(person, onePlane(), kProjection);
    const Image out = c.output().read();
    EXPECT_EQ(rgbaAt(out, 37, 5), cv::Vec4b(30, 20, 10, 255));
    EXPECT_EQ(rgbaAt(out, 36, 5), cv::Vec4b(0, 255, 0, 255));
}

// Only the rows of the occupied tiles are uploaded: a tile drawn again must
// show none of what the last frame's person left in the texture, in any of
// its rows, and a tile left empty is not drawn at all.
TEST(Compositor, aTileShowsNothingOfTheLastFramesPerson) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    const glm::ivec2 size{96, 96};
    Compositor c(size);
    const cv::Mat frame(size.y, size.x, CV_8UC3, cv::Scalar(90, 90, 90));
    cv::Mat person(size.y, size.x, CV_8UC4, cv::Scalar(0, 0, 0, 0));
    person(cv::Rect(0, 32, 96, 32)).setTo(cv::Scalar(0, 0, 200, 255));  // a band of tile rows, solid red
    c.begin(frame, {});
    c.person(person, onePlane(), kProjection);
    EXPECT_EQ(rgbaAt(c.output().read(), 40, 40), cv::Vec4b(200, 0, 0, 255));
    person.setTo(cv::Scalar(0, 0, 0, 0));
    person.at<cv::Vec4b>(60, 40) = cv::Vec4b(0, 200, 0, 255);  // one green pixel, low in the band's last tile row
    c.begin(frame, {});
    c.person(person, onePlane(), kProjection);
    const Image out = c.output().read();
    EXPECT_EQ(c.personTiles(), 1u);
    EXPECT_EQ(rgbaAt(out, 40, 60), cv::Vec4b(0, 200, 0, 255));
    for (const int y : {32, 40, 56, 59, 61, 63})  // the band; its tile (rows 56-63) above and below the pixel
        EXPECT_EQ(rgbaAt(out, 40, y), cv::Vec4b(90, 90, 90, 255)) << "row " << y;
    EXPECT_EQ(rgbaAt(out, 10, 40), cv::Vec4b(90, 90, 90, 255));  // a tile of the last frame's person, empty now
    EXPECT_EQ(rgbaAt(out, 47, 60), cv::Vec4b(90, 90, 90, 255));  // the tile's last column
}

// The tiles a pipelined station finds on its capture thread: only where
// alpha is not 0, at a ragged edge too, and the image rows they span; found
// again into the same value, nothing of the last layer's stays.
TEST(Compositor, findTilesKeepsTheTilesWithAlphaAndTheRowsTheySpan) {
    cv::Mat person(70, 100, CV_8UC4, cv::Scalar(0, 0, 0, 0));  // 13 x 9 tiles, the last column and row partial
    person.at<cv::Vec4b>(69, 99) = cv::Vec4b(0, 0, 0, 1);      // the last pixel of the last tile
    person.at<cv::Vec4b>(40, 5) = cv::Vec4b(9, 9, 9, 0);       // colour without alpha: no tile
    PersonTiles tiles;
    Compositor::findTiles(person, tiles);
    EXPECT_EQ(tiles.count, 1u);
    EXPECT_EQ(tiles.quads.size(), 12u);
    EXPECT_EQ(tiles.rows, glm::ivec2(64, 70));
    person.at<cv::Vec4b>(3, 40) = cv::Vec4b(0, 0, 0, 255);
    Compositor::findTiles(person, tiles);
    EXPECT_EQ(tiles.count, 2u);
    EXPECT_EQ(tiles.quads.size(), 24u);
    EXPECT_EQ(tiles.rows, glm::ivec2(0, 70));
    Compositor::findTiles(cv::Mat(70, 100, CV_8UC4, cv::Scalar(0, 0, 0, 0)), tiles);
    EXPECT_EQ(tiles.count, 0u);
    EXPECT_TRUE(tiles.quads.empty());
    Compositor::findTiles(person, tiles);
    Compositor::findTiles(cv::Mat(70, 100, CV_8UC3, cv::Scalar(255, 255, 255)), tiles);
    EXPECT_EQ(tiles.count, 0u);
    EXPECT_TRUE(tiles.quads.empty());
}

TEST(Compositor, halfTransparentPersonBlendsPremultiplied) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    const glm::ivec2 size{16, 16};
    Compositor c(size);
    cv::Mat frame(size.y, size.x, CV_8UC3, cv::Scalar(0, 0, 0));
    cv::Mat person(size.y, size.x, CV_8UC4, cv::Scalar(0, 100, 0, 128));  // green at half alpha, premultiplied
    c.begin(frame, {});
    paint(size, {0, 0, 16, 16}, glm::vec4(0, 0, 1, 1));
    c.beginHoldout();
    c.endHoldout();
    c.person(person, onePlane(), kProjection);
    const cv::Vec4b p = rgbaAt(c.output().read(), 8, 8);
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
    c.begin(frame, {.backdropVideo = false, .backdropColor = {0.2f, 0.2f, 0.2f, 1.0f}});
    c.person(person, onePlane(), kProjection);
    EXPECT_EQ(rgbaAt(c.output().read(), 3, 3), cv::Vec4b(51, 51, 51, 255));
    EXPECT_EQ(c.personTiles(), 0u);
}

TEST(Compositor, videoRowsKeepTheirOrder) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    const glm::ivec2 size{8, 6};
    Compositor c(size);
    cv::Mat frame(size.y, size.x, CV_8UC3, cv::Scalar(0, 0, 0));
    frame.row(0).setTo(cv::Scalar(255, 0, 0));  // top row blue
    c.begin(frame, {});
    c.person(cv::Mat(size.y, size.x, CV_8UC4, cv::Scalar::all(0)), onePlane(), kProjection);
    const Image out = c.output().read();
    EXPECT_EQ(rgbaAt(out, 4, 0), cv::Vec4b(0, 0, 255, 255));
    EXPECT_EQ(rgbaAt(out, 4, 5), cv::Vec4b(0, 0, 0, 255));
}

}  // namespace
