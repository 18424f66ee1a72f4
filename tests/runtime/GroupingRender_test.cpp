// Grouping proxies on screen: boxes are blended over what is behind them,
// impostors show the baked members, and both draw far fewer triangles.

#include "graph/scenes/ForestExperiment.hpp"
#include "runtime/gl/GlContext.hpp"
#include "runtime/gl/RenderTarget.hpp"
#include "runtime/render/ImpostorBaker.hpp"
#include "runtime/render/Renderer.hpp"
#include "runtime/station/ImageFile.hpp"
#include "tools/bench/report/ImageDifference.hpp"

#include <gtest/gtest.h>

using namespace arcomp;

namespace {

struct Shot {
    Image image;
    std::size_t triangles;
};

Shot render(ForestExperiment& f, Renderer& renderer, ForestMode mode, GroupingProxy proxy,
            const glm::vec4& background) {
    RenderTarget target(f.view.viewport);
    target.bind();
    const DrawList& list = f.select(mode, 0.1f, proxy);
    renderer.draw(f.world.scene, list, f.view, {.clearColor = background});
    return {target.read(), renderer.trianglesDrawn()};
}

const std::uint8_t* pixel(const Image& img, glm::ivec2 p) {
    return &img.rgba[(static_cast<std::size_t>(p.y) * static_cast<std::size_t>(img.width) +
                      static_cast<std::size_t>(p.x)) *
                     4];
}

// Where the forest's centre lands on screen.
glm::ivec2 screenOf(const View& v, const glm::vec3& p) {
    const glm::vec4 c = v.viewProjection() * glm::vec4(p, 1.0f);
    const glm::vec2 ndc = glm::vec2(c) / c.w;
    return {int((ndc.x * 0.5f + 0.5f) * float(v.viewport.x)), int((0.5f - ndc.y * 0.5f) * float(v.viewport.y))};
}

void keepOnFailure(const char* name, const Image& img) {
    if (::testing::Test::HasFailure()) writePng(std::string(ARCOMP_TEST_OUTPUT) + "/" + name + ".png", img);
}

}  // namespace

TEST(GroupingRender, boxProxyIsBlendedOverTheBackground) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    ForestExperiment f(ForestColouring::Green, {}, {320, 180});
    Renderer renderer;
    const glm::vec4 blue{0.0f, 0.0f, 1.0f, 1.0f};
    const Shot grouped = render(f, renderer, ForestMode::Grouped, GroupingProxy::Box, blue);
    EXPECT_EQ(grouped.triangles, 12u) << "the whole green forest is one box at Ωt = 0.1";
    const glm::ivec2 centre = screenOf(f.view, f.world.scene.worldBound(f.forest.grouping).center);
    const std::uint8_t* p = pixel(grouped.image, centre);
    // Drawn in the blended pass over an opaque background the result stays
    // opaque (an unblended 0.7-alpha box would leave alpha at 178), and the
    // blue behind shows through the green box.
    EXPECT_EQ(p[3], 255);
    EXPECT_GT(p[1], 60) << "the box's green";
    EXPECT_GT(p[2], 40) << "the background's blue through it";
    EXPECT_LT(p[2], 230);
    keepOnFailure("grouping-box", grouped.image);
}

TEST(GroupingRender, impostorLooksCloserToTheFullForestThanNothing) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    ForestExperiment f(ForestColouring::Green, {}, {320, 180});
    EXPECT_GT(
        bakeImpostors(f.world.scene, f.forest.grouping, f.world.grouping, {.pixelsPerUnit = 0.3f, .eye = f.view.eye}),
        0u);
    Renderer renderer;
    const glm::vec4 sky{0.6f, 0.7f, 0.8f, 1.0f};
    const Shot full = render(f, renderer, ForestMode::Full, GroupingProxy::Box, sky);
    const Shot impostor = render(f, renderer, ForestMode::Grouped, GroupingProxy::Impostor, sky);
    EXPECT_EQ(full.triangles, 3360u);
    EXPECT_EQ(impostor.triangles, 2u);
    // Against an image of the sky alone, the impostor must be much closer.
    Image empty = full.image;
    const std::uint8_t* corner = pixel(full.image, {0, 0});  // sky only
    for (std::size_t i = 0; i < empty.rgba.size(); i += 4) std::copy_n(corner, 4, &empty.rgba[i]);
    EXPECT_GT(psnr(full.image, impostor.image), psnr(full.image, empty) + 3.0);
    keepOnFailure("grouping-impostor", impostor.image);
}
