// Contact shadows on the video: where a box's shadow falls on the floor for
// a given light, how dark it is, that its edge is soft, and that nothing
// else in the picture changes.
#include "runtime/composite/ShadowCatcher.hpp"

#include "graph/core/SelectPass.hpp"
#include "runtime/composite/Compositor.hpp"
#include "runtime/gl/GlContext.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include <set>
#include <vector>

using namespace arcomp;

namespace {

TEST(ShadowCatcher, floorShadowMatrixDropsEachPointAlongTheLight) {
    const glm::vec4 p(1.0f, 2.0f, 3.0f, 1.0f);
    const glm::vec4 straightDown = floorShadowMatrix({0.0f, 1.0f, 0.0f}) * p;
    EXPECT_FLOAT_EQ(straightDown.x, 1.0f);
    EXPECT_FLOAT_EQ(straightDown.y, 0.0f);
    EXPECT_FLOAT_EQ(straightDown.z, 3.0f);
    // A light 45 degrees up in +x: the shadow falls 2 m towards -x.
    const glm::vec4 slanted = floorShadowMatrix(glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f))) * p;
    EXPECT_NEAR(slanted.x, -1.0f, 1e-5f);
    EXPECT_NEAR(slanted.y, 0.0f, 1e-6f);
    EXPECT_NEAR(slanted.z, 3.0f, 1e-5f);
}

// A white 1 m cube standing on the floor at (x, z); its transform node.
NodeId addCubeOnTheFloor(Scene& scene, glm::vec2 at = {0.0f, 0.0f}) {
    const auto white = scene.addMaterial({.name = "white", .baseColor = {1, 1, 1, 1}});
    const NodeId cube = scene.addTransform(scene.root(), glm::translate(glm::mat4(1), {at.x, 0.5f, at.y}));
    scene.addMesh(cube, {scene.addGeometry(makeBox({1.0f, 1.0f, 1.0f})), white});
    scene.update();
    return cube;
}

struct Shadowed {
    Image image;
    cv::Mat grey;  // the output's luminance, rows top first
    View view;
    std::size_t pixels = 0;
};

// 1 m cubes standing on the floor at `cubes` (x, z; the origin by default), over
// a uniform grey video, seen from 6 m up and 6 m back; only the shadows are
// drawn, not the cubes.
Shadowed castOnGrey(const glm::vec3& light, float strength, const std::vector<glm::vec2>& cubes = {{0.0f, 0.0f}},
                    ShadowCatcher::Tiles tiles = ShadowCatcher::Tiles::Auto, glm::ivec2 size = {320, 240}) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    World world;
    Scene& scene = world.scene;
    for (const glm::vec2 at : cubes) addCubeOnTheFloor(scene, at);
    Shadowed out;
    out.view = View::lookAt({0, 6, 6}, {0, 0, 0}, {0, 1, 0}, 50, size);
    DrawList list;
    select(world, out.view, {}, list);
    Compositor compositor(size);
    compositor.begin(cv::Mat(size.y, size.x, CV_8UC3, cv::Scalar(200, 200, 200)), {});
    Renderer renderer;
    ShadowCatcher shadows(size, tiles);
    shadows.cast(scene, list, out.view, {.enabled = true, .light = glm::normalize(light), .strength = strength},
                 renderer, compositor.output());
    out.pixels = shadows.pixelsCovered();
    out.image = compositor.output().read();
    out.grey.create(size.y, size.x, CV_8UC1);
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x)
            out.grey.at<std::uint8_t>(y, x) = out.image.rgba[(static_cast<std::size_t>(y) * size.x + x) * 4 + 1];
    return out;
}

cv::Point2d pixelOf(const View& v, const glm::vec3& p) {
    const glm::vec4 clip = v.viewProjection() * glm::vec4(p, 1.0f);
    return {(clip.x / clip.w * 0.5 + 0.5) * v.viewport.x, (0.5 - clip.y / clip.w * 0.5) * v.viewport.y};
}

TEST(ShadowCatcher, theShadowFallsAwayFromTheLightDarkenedByTheStrength) {
    const Shadowed s = castOnGrey({1.0f, 1.0f, 0.0f}, 0.5f);
    // The light is 45 degrees up in +x: the cube's shadow spans x in [-1.5, 0.5] on the floor.
    const cv::Point2d inside = pixelOf(s.view, {-0.9f, 0.0f, 0.0f}), away = pixelOf(s.view, {1.6f, 0.0f, 0.0f});
    EXPECT_NEAR(s.grey.at<std::uint8_t>(cv::Point(inside)), 100, 2);
    EXPECT_EQ(s.grey.at<std::uint8_t>(cv::Point(away)), 200);
    // Only the shadow changed, and only inside the rectangle the catcher reported.
    cv::Mat darker = s.grey < 199;
    const cv::Moments m = cv::moments(darker, true);
    ASSERT_GT(m.m00, 100.0);
    EXPECT_LE(m.m00, static_cast<double>(s.pixels));
    const cv::Point2d centre = pixelOf(s.view, {-0.5f, 0.0f, 0.0f});
    EXPECT_NEAR(m.m10 / m.m00, centre.x, 3.0);
    EXPECT_NEAR(m.m01 / m.m00, centre.y, 3.0);
    // A soft edge: the row through the middle climbs from the shadow to the
    // video through several grey levels over a few pixels, not in one step.
    const int row = static_cast<int>(centre.y);
    std::set<int> levels;
    for (int x = static_cast<int>(inside.x); x < static_cast<int>(away.x); ++x) {
        const int g = s.grey.at<std::uint8_t>(row, x);
        if (g > 102 && g < 198) levels.insert(g);
    }
    EXPECT_GE(levels.size(), 3u);
}

TEST(ShadowCatcher, aLightOnTheOtherSideMovesTheShadowThereAndNoStrengthLeavesTheVideo) {
    const Shadowed left = castOnGrey({1.0f, 1.0f, 0.0f}, 0.5f), right = castOnGrey({-1.0f, 1.0f, 0.0f}, 0.5f);
    const cv::Moments l = cv::moments(left.grey < 199, true), r = cv::moments(right.grey < 199, true);
    ASSERT_GT(l.m00, 100.0);
    ASSERT_GT(r.m00, 100.0);
    EXPECT_LT(l.m10 / l.m00 + 20.0, r.m10 / r.m00);
    const Shadowed none = castOnGrey({1.0f, 1.0f, 0.0f}, 0.0f);
    EXPECT_EQ(cv::countNonZero(none.grey != 200), 0);
}

// Two cubes far apart, across the view and in depth: the pass covers the
// tiles around each shadow, not the rectangle spanning both. Two close
// together, their rectangles overlapping: each pixel is darkened once, so
// each shadow is as dark as a cube's alone.
TEST(ShadowCatcher, eachShadowIsDrawnOnItsOwnTilesAndEachPixelOnce) {
    const glm::vec3 light{1.0f, 1.0f, 0.0f};
    // The rectangles' tiles, as a GPU shades them (a software rasterizer shades fewer).
    const auto rectangles = ShadowCatcher::Tiles::Rectangles;
    const Shadowed one = castOnGrey(light, 0.5f, {{0.0f, 0.0f}}, rectangles),
                   apart = castOnGrey(light, 0.5f, {{-3.0f, -3.0f}, {3.0f, 2.0f}}, rectangles);
    for (const glm::vec2 shadow : {glm::vec2(-3.9f, -3.0f), glm::vec2(2.1f, 2.0f)})
        EXPECT_NEAR(apart.grey.at<std::uint8_t>(cv::Point(pixelOf(apart.view, {shadow.x, 0.0f, shadow.y}))), 100, 2);
    EXPECT_LT(apart.pixels, 5 * one.pixels / 2) << "each shadow's tiles, not the span of both";

    const Shadowed close = castOnGrey(light, 0.5f, {{-0.7f, 0.0f}, {0.7f, 0.0f}}, rectangles);
    for (const float x : {-1.6f, -1.0f, 0.2f})  // in the left cube's shadow, and in the right one's
        EXPECT_NEAR(close.grey.at<std::uint8_t>(cv::Point(pixelOf(close.view, {x, 0.0f, 0.0f}))), 100, 2) << "x " << x;
}

// Shading only the tiles the mask reaches changes no pixel: elsewhere the
// shade is exactly 1. Sizes that are not multiples of the mask's 4 or the
// tiles' 8, cubes at the screen's edge and a low light with long shadows.
TEST(ShadowCatcher, theMasksTilesShadeWhatTheRectanglesShadeOnFewerPixels) {
    const std::vector<glm::vec2> cubes = {{-3.0f, -3.0f}, {3.0f, 2.0f}, {0.0f, 0.0f}, {5.5f, 0.0f}, {-1.0f, 3.5f}};
    for (const glm::ivec2 size : {glm::ivec2(320, 240), glm::ivec2(203, 117)})
        for (const glm::vec3 light : {glm::vec3(1.0f, 1.0f, 0.0f), glm::vec3(-1.0f, 0.4f, 0.5f)}) {
            const Shadowed rectangles = castOnGrey(light, 0.6f, cubes, ShadowCatcher::Tiles::Rectangles, size);
            const Shadowed mask = castOnGrey(light, 0.6f, cubes, ShadowCatcher::Tiles::Mask, size);
            ASSERT_GT(cv::countNonZero(rectangles.grey < 199), 100);
            EXPECT_EQ(mask.image.rgba, rectangles.image.rgba) << size.x << "x" << size.y << ", light x " << light.x;
            EXPECT_LT(mask.pixels, rectangles.pixels);
        }
}

// A static installation draws its shadow mask once; an object that moves
// draws it again, and its shadow moves with it.
TEST(ShadowCatcher, theMaskIsDrawnAgainOnlyWhenAnObjectMoves) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    const glm::ivec2 size{160, 120};
    World world;
    Scene& scene = world.scene;
    const NodeId cube = addCubeOnTheFloor(scene);
    const View view = View::lookAt({0, 6, 6}, {0, 0, 0}, {0, 1, 0}, 50, size);
    Compositor compositor(size);
    Renderer renderer;
    ShadowCatcher shadows(size);
    const ShadowConfig light{.enabled = true, .light = glm::normalize(glm::vec3(1, 1, 0)), .strength = 0.5f};
    auto cast = [&] {
        DrawList list;
        select(world, view, {}, list);
        compositor.begin(cv::Mat(size.y, size.x, CV_8UC3, cv::Scalar(200, 200, 200)), {});
        shadows.cast(scene, list, view, light, renderer, compositor.output());
        const Image img = compositor.output().read();
        double darkX = 0, dark = 0;
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x)
                if (img.rgba[(static_cast<std::size_t>(y) * size.x + x) * 4 + 1] < 199) darkX += x, ++dark;
        return darkX / std::max(dark, 1.0);
    };
    const double first = cast(), again = cast();
    EXPECT_EQ(shadows.masksDrawn(), 1u);
    EXPECT_DOUBLE_EQ(first, again);
    scene.setLocal(cube, glm::translate(glm::mat4(1), {1.0f, 0.5f, 0.0f}));
    scene.update();
    const double moved = cast();
    EXPECT_EQ(shadows.masksDrawn(), 2u);
    EXPECT_GT(moved, first + 5.0);  // a metre to the right is about 14 pixels here
}

}  // namespace
