// Headless rendering under both context kinds: coverage, colour at known
// points, the four shading levels, and GL 3.3 against ES 3.0.

#include "graph/core/SelectPass.hpp"
#include "runtime/gl/GlContext.hpp"
#include "runtime/gl/RenderTarget.hpp"
#include "runtime/render/Renderer.hpp"
#include "runtime/station/ImageFile.hpp"
#include "tests/support/ImagePixels.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cstdlib>

using namespace arcomp;

namespace {

double coverage(const Image& img) {
    return static_cast<double>(test::coveredPixels(img)) / static_cast<double>(img.width * img.height);
}

// Mean absolute difference per channel, 0..255.
double meanDifference(const Image& a, const Image& b) {
    double sum = 0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i) sum += std::abs(int(a.rgba[i]) - int(b.rgba[i]));
    return sum / static_cast<double>(a.rgba.size());
}

// A red box on the left, a green sphere on the right, seen from +Z;
// `whiteTexture`: each with a white base colour texture, which changes
// nothing but which program draws it (Renderer.cpp, UNTEXTURED).
Image renderTestScene(GlRequest request, Shading shading, glm::ivec2 size = {320, 240}, bool whiteTexture = false) {
    auto ctx = HeadlessContext::create(request);
    World world;
    Scene& scene = world.scene;
    Material redMaterial{.name = "red", .baseColor = {1, 0, 0, 1}};
    Material greenMaterial{.name = "green", .baseColor = {0, 1, 0, 1}};
    if (whiteTexture) {
        const auto white =
            static_cast<int>(scene.addImage({.width = 2, .height = 2, .rgba = std::vector<std::uint8_t>(16, 255)}));
        redMaterial.baseColorTexture.image = greenMaterial.baseColorTexture.image = white;
    }
    const auto red = scene.addMaterial(redMaterial);
    const auto green = scene.addMaterial(greenMaterial);
    const NodeId left = scene.addTransform(scene.root(), glm::translate(glm::mat4(1), {-1.2f, 0, 0}));
    scene.addMesh(left, {scene.addGeometry(makeBox({1.5f, 1.5f, 1.5f})), red});
    const NodeId right = scene.addTransform(scene.root(), glm::translate(glm::mat4(1), {1.2f, 0, 0}));
    scene.addMesh(right, {scene.addGeometry(makeUvSphere(0.8f, 32, 16)), green});
    scene.update();
    const View view = View::lookAt({0, 0, 6}, {0, 0, 0}, {0, 1, 0}, 45, size);
    RenderTarget target(size);
    target.bind();
    Renderer renderer;
    DrawList list;
    select(world, view, {.shading = shading}, list);
    EXPECT_EQ(list.items.size(), 2u);
    renderer.draw(scene, list, view, {.clearColor = glm::vec4(0, 0, 0, 0)});
    return target.read();
}

void saveOnFailure(const Image& img, const std::string& name) {
    if (::testing::Test::HasFailure()) writePng(std::string(ARCOMP_TEST_OUTPUT) + "/" + name + ".png", img);
}

class RendererOnEachApi : public ::testing::TestWithParam<GlRequest> {};

}  // namespace

TEST_P(RendererOnEachApi, drawsObjectsWhereTheyStandInTheirColours) {
    const Image img = renderTestScene(GetParam(), Shading::Phong);
    const test::Pixel corner = test::pixelAt(img, 2, 2);
    EXPECT_EQ(corner.a, 0) << "background stays transparent";
    const test::Pixel box = test::pixelAt(img, 320 / 2 - 55, 120);
    EXPECT_EQ(box.a, 255);
    // Beside its colour, a dielectric reflects about 4% of the (grey) studio
    // in every channel: sRGB 30-40 where it has none of its own.
    EXPECT_GT(box.r, 100);
    EXPECT_LT(box.g, 45);
    const test::Pixel sphere = test::pixelAt(img, 320 / 2 + 55, 120);
    EXPECT_EQ(sphere.a, 255);
    EXPECT_GT(sphere.g, 100);
    EXPECT_LT(sphere.r, 45);
    const double c = coverage(img);
    EXPECT_GT(c, 0.10);
    EXPECT_LT(c, 0.35);
    saveOnFailure(img, "renderer-colours");
}

TEST_P(RendererOnEachApi, eachShadingLevelGivesADifferentImageWithTheSameCoverage) {
    std::vector<Image> images;
    for (Shading s : {Shading::Unlit, Shading::Flat, Shading::Gouraud, Shading::Phong})
        images.push_back(renderTestScene(GetParam(), s));
    for (std::size_t i = 0; i < images.size(); ++i) {
        EXPECT_NEAR(coverage(images[i]), coverage(images[0]), 0.002);
        for (std::size_t j = i + 1; j < images.size(); ++j)
            EXPECT_GT(meanDifference(images[i], images[j]), 0.05) << "levels " << i << " and " << j << " look the same";
    }
    // Unlit shows the base colour itself: full red on the box.
    EXPECT_EQ(test::pixelAt(images[0], 320 / 2 - 55, 120).r, 255);
}

INSTANTIATE_TEST_SUITE_P(Apis, RendererOnEachApi, ::testing::Values(GlRequest::Gl33, GlRequest::Es3),
                         [](const auto& info) { return info.param == GlRequest::Gl33 ? "gl33" : "es3"; });

// Materials without textures are drawn by a program compiled without the
// texture slots; it must give the very image the general program gives.
TEST_P(RendererOnEachApi, aMaterialWithoutTexturesDrawsAsOneWithAWhiteTexture) {
    for (int s = 0; s < kShadingCount; ++s) {
        const auto shading = static_cast<Shading>(s);
        const Image plain = renderTestScene(GetParam(), shading),
                    white = renderTestScene(GetParam(), shading, {320, 240}, true);
        EXPECT_GT(coverage(plain), 0.1);
        EXPECT_TRUE(plain.rgba == white.rgba)
            << toString(shading) << ": mean difference " << meanDifference(plain, white);
    }
}

TEST(Renderer, desktopAndEsImagesAgree) {
    const Image gl = renderTestScene(GlRequest::Gl33, Shading::Phong);
    const Image es = renderTestScene(GlRequest::Es3, Shading::Phong);
    EXPECT_LT(meanDifference(gl, es), 0.5);
}

TEST(HeadlessContext, autoGivesDesktopGlHere) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    EXPECT_EQ(ctx->api(), GlApiKind::Gl33);
    EXPECT_NE(glDescription().find("gl33"), std::string::npos);
}
