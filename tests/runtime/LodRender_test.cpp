// The gaze-acuity LOD seen in an image: a row of spheres across the view,
// gaze on the leftmost; each level has its own colour, so the written image
// shows where the levels fall off, and the pixels are checked against k1.

#include "graph/core/SelectPass.hpp"
#include "graph/lod/GazeAcuity.hpp"
#include "graph/lod/Lod.hpp"
#include "runtime/gl/GlContext.hpp"
#include "runtime/gl/RenderTarget.hpp"
#include "runtime/render/Renderer.hpp"
#include "runtime/station/ImageFile.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using namespace arcomp;

TEST(LodRender, levelsFallOffToTheRightOfTheGazeInTheImage) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    World world;
    Scene& scene = world.scene;
    LodTable& lods = world.lods;
    const glm::vec4 levelColors[3] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}};
    std::uint32_t geometry[3], material[3];
    const int tessellation[3][2] = {{32, 16}, {12, 6}, {6, 4}};
    for (int l = 0; l < 3; ++l) {
        geometry[l] = scene.addGeometry(makeUvSphere(1.0f, tessellation[l][0], tessellation[l][1]));
        material[l] = scene.addMaterial({.name = "level" + std::to_string(l), .baseColor = levelColors[l]});
    }
    LodNode node;
    node.policy = LodPolicy::GazeAcuity;
    node.setThresholds({0.5f, 0.1f});
    std::vector<glm::vec3> positions;
    for (int k = 0; k <= 10; ++k) {
        const glm::vec3 at{-15.0f + 3.0f * static_cast<float>(k), 0.0f, -20.0f};
        const NodeId t = scene.addTransform(scene.root(), glm::translate(glm::mat4(1.0f), at));
        const NodeId lod = scene.addNode(t, NodeKind::Lod, lods.add(node));
        for (int l = 0; l < 3; ++l) scene.addMesh(lod, {geometry[l], material[l]});
        positions.push_back(at);
    }
    scene.update();
    const glm::ivec2 size{1280, 360};
    const View view = View::lookAt({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 40.0f, size);
    const glm::vec3 gaze = glm::normalize(positions.front());
    DrawList list;
    select(world, view, {.shading = Shading::Unlit, .gaze = gaze}, list);
    RenderTarget target(size);
    target.bind();
    Renderer renderer;
    renderer.draw(scene, list, view);
    const Image image = target.read();
    writePng(std::string(ARCOMP_TEST_OUTPUT) + "/lod-gaze-row.png", image);

    int previousLevel = 0;
    for (const glm::vec3& p : positions) {
        const glm::vec4 clip = view.viewProjection() * glm::vec4(p, 1.0f);
        const int x = static_cast<int>((clip.x / clip.w * 0.5f + 0.5f) * static_cast<float>(size.x));
        const int y = size.y / 2;
        const std::uint8_t* px = &image.rgba[(static_cast<std::size_t>(y) * size.x + static_cast<std::size_t>(x)) * 4];
        const float k1 = eccentricityAcuity(angleDegrees(gaze, p), GazeAcuityParams{});
        const int expected = k1 >= 0.5f ? 0 : (k1 >= 0.1f ? 1 : 2);
        int seen = -1;
        for (int l = 0; l < 3; ++l)
            if (px[l] > 200 && px[(l + 1) % 3] < 30 && px[(l + 2) % 3] < 30) seen = l;
        EXPECT_EQ(seen, expected) << "sphere at x = " << p.x;
        EXPECT_GE(seen, previousLevel) << "levels must not get finer away from the gaze";
        previousLevel = seen;
    }
    EXPECT_EQ(previousLevel, 2);
}
