// GPU skinning poses normals with positions: a square turned by its joint
// is lit as the same square turned by its node, at every shading level, on
// OpenGL 3.3 and on OpenGL ES 3.0.

#include "graph/core/SelectPass.hpp"
#include "runtime/gl/GlContext.hpp"
#include "runtime/gl/RenderTarget.hpp"
#include "runtime/render/Renderer.hpp"
#include "runtime/station/ImageFile.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cstdlib>

using namespace arcomp;

namespace {

constexpr glm::ivec2 kShadedSize{64, 64};

// A unit square facing +Z, seen from +X once turned a quarter about Y.
Geometry square() {
    Geometry g;
    g.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    g.normals.assign(4, {0, 0, 1});
    g.indices = {0, 1, 2, 0, 2, 3};
    g.finalize();
    return g;
}

const glm::mat4 kQuarterTurn = glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), {0, 1, 0});

Image render(GlRequest api, Shading shading, bool skinned) {
    auto ctx = HeadlessContext::create(api);
    World world;
    Scene& scene = world.scene;
    Material m;
    m.baseColor = glm::vec4(0.8f, 0.5f, 0.3f, 1.0f);
    const std::uint32_t material = scene.addMaterial(m);
    if (skinned) {
        Geometry g = square();
        g.joints.assign(4, {0, 0, 0, 0});
        g.weights.assign(4, {1, 0, 0, 0});
        const NodeId place = scene.addTransform(scene.root(), glm::mat4(1.0f));
        const NodeId joint[1] = {scene.addTransform(scene.root(), kQuarterTurn)};
        const glm::mat4 bind[1] = {glm::mat4(1.0f)};
        const std::uint32_t skin = scene.addSkin(place, joint, bind);
        const NodeId mesh = scene.addMesh(place, {scene.addGeometry(std::move(g)), material, skin});
        scene.setLocalBound(mesh, {glm::vec3(0.0f), 1.5f});
    } else {
        scene.addMesh(scene.addTransform(scene.root(), kQuarterTurn), {scene.addGeometry(square()), material});
    }
    scene.update();
    const View view = View::lookAt({4.0f, 0, 0}, {0, 0, 0}, {0, 1, 0}, 45.0f, kShadedSize);
    RenderTarget target(kShadedSize);
    target.bind();
    Renderer renderer;
    DrawList list;
    select(world, view, {.shading = shading}, list);
    renderer.draw(scene, list, view, {.lightDirection = {1, 0, 0}});
    return target.read();
}

class SkinnedShading : public ::testing::TestWithParam<GlRequest> {};

TEST_P(SkinnedShading, aSquareTurnedByItsJointIsLitAsOneTurnedByItsNode) {
    for (const Shading shading : {Shading::Flat, Shading::Gouraud, Shading::Phong}) {
        const Image rigid = render(GetParam(), shading, false);
        const Image skinned = render(GetParam(), shading, true);
        const std::size_t centre =
            (static_cast<std::size_t>(kShadedSize.y / 2) * kShadedSize.x + kShadedSize.x / 2) * 4;
        ASSERT_GT(rigid.rgba[centre + 3], 0) << "the turned square faces the camera";
        int worst = 0;
        for (std::size_t i = 0; i < rigid.rgba.size(); ++i)
            worst = std::max(worst, std::abs(int(rigid.rgba[i]) - int(skinned.rgba[i])));
        EXPECT_LE(worst, 2) << "shading level " << static_cast<int>(shading);
        if (HasFailure()) {
            const std::string name = std::string(ARCOMP_TEST_OUTPUT) + "/skinned-shading-" +
                                     std::to_string(static_cast<int>(shading)) +
                                     (GetParam() == GlRequest::Es3 ? "-es3" : "-gl33");
            writePng(name + "-rigid.png", rigid);
            writePng(name + "-skinned.png", skinned);
            return;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Apis, SkinnedShading, ::testing::Values(GlRequest::Gl33, GlRequest::Es3),
                         [](const auto& info) { return info.param == GlRequest::Gl33 ? "gl33" : "es3"; });

}  // namespace
