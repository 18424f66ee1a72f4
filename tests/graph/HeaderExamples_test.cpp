// The usage examples at the top of graph/ headers, compiled: an example that
// no longer matches its API breaks this build instead of misleading a reader.
// Each test holds its header's lines as written there, then checks them.

#include "graph/budget/RecursiveLeastSquares.hpp"
#include "graph/core/Scene.hpp"
#include "graph/core/SelectPass.hpp"
#include "graph/core/World.hpp"
#include "graph/io/Base64.hpp"
#include "graph/io/DataUri.hpp"
#include "graph/io/GltfWriter.hpp"
#include "graph/lod/GazeAcuity.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using namespace arcomp;

TEST(HeaderExamples, scene) {
    Geometry g = makeBox({1, 1, 1});
    // graph/core/Scene.hpp
    Scene scene;
    NodeId t = scene.addTransform(scene.root(), glm::translate(glm::mat4(1.0f), {0, 0, -5}));
    scene.addMesh(t, {scene.addGeometry(std::move(g)), scene.addMaterial({})});
    scene.update();  // world matrices and bounds of what changed
    EXPECT_NEAR(scene.bound().center.z, -5.0f, 1e-5f);
}

TEST(HeaderExamples, gazeAcuity) {
    const glm::vec3 eye(0.0f), eyeNow(0.0f), gaze(0, 0, -1), center(0, 0, -10), localCenter(0.0f);
    const glm::mat4 world = glm::translate(glm::mat4(1.0f), center), worldNow = world;
    const float radius = 1.0f, dt = 0.04f;
    TrackedPoint last = trackPoint(eye, world, localCenter, radius);
    // graph/lod/GazeAcuity.hpp
    GazeAcuityParams p;  // a = 5°, c1 = 6°, c2 = 30°/s
    float theta = angleDegrees(gaze, center - eye);
    float speed = angularSpeed(last, worldNow, eyeNow, dt);    // degrees per second
    float k = gazeAcuity(theta, speed, p);                     // in [0, 1]
    last = trackPoint(eyeNow, worldNow, localCenter, radius);  // for the next frame
    EXPECT_FLOAT_EQ(k, 1.0f);                                  // looked at, standing still
    EXPECT_TRUE(last.valid);
}

TEST(HeaderExamples, recursiveLeastSquares) {
    // graph/budget/RecursiveLeastSquares.hpp, fed y = 0.002 x + 3
    RecursiveLeastSquares rls(2, 0.98);  // θ = (A, B), λ = 0.98
    for (double pixels : {1000.0, 5000.0, 20000.0, 80000.0, 3000.0}) {
        const double measuredMs = 0.002 * pixels + 3.0;
        const double x[] = {pixels, 1.0};
        rls.add(x, measuredMs);
    }
    double a = rls.parameters()[0];
    EXPECT_NEAR(a, 0.002, 1e-4);
}

TEST(HeaderExamples, world) {
    LodNode settings;
    settings.levelCount = 2;
    settings.thresholds[0] = 10.0f;
    const View view = View::lookAt({0, 0, 20}, {0, 0, 0}, {0, 1, 0}, 60.0f, {64, 64});
    const double t = 0.0;
    // graph/core/World.hpp
    World world;
    const MeshPart fine{world.scene.addGeometry(makeUvSphere(1.0f, 32, 16)), world.scene.addMaterial({})};
    const MeshPart coarse{world.scene.addGeometry(makeUvSphere(1.0f, 8, 4)), fine.material};
    const NodeId lod = world.scene.addNode(world.scene.root(), NodeKind::Lod, world.lods.add(settings));
    world.scene.addMesh(lod, fine);
    world.scene.addMesh(lod, coarse);
    world.scene.update();
    DrawList list;
    select(world, view, {.shading = Shading::Phong, .timeSeconds = t}, list);
    ASSERT_EQ(list.items.size(), 1u);
    EXPECT_EQ(list.items[0].level, 1);  // 20 away, past the threshold at 10
}

TEST(HeaderExamples, dataUriAndBase64) {
    // graph/io/DataUri.hpp
    DataUri d = decodeDataUri("data:application/gltf-buffer,0");
    EXPECT_EQ(d.mediaType, "application/gltf-buffer");
    EXPECT_EQ(d.bytes, std::vector<std::uint8_t>{'0'});
    EXPECT_TRUE(d.error.empty());
    // graph/io/Base64.hpp
    const std::vector<std::uint8_t> bytes{1, 2, 3, 250};
    std::string uri = "data:application/octet-stream;base64," + base64(bytes.data(), bytes.size());
    std::optional<std::vector<std::uint8_t>> back = fromBase64(uri.substr(uri.find(',') + 1));
    EXPECT_EQ(back, bytes);
    EXPECT_EQ(decodeDataUri(uri).bytes, bytes);
    EXPECT_EQ(decodeDataUri("data:,a%20b").bytes, (std::vector<std::uint8_t>{'a', ' ', 'b'}));
    EXPECT_FALSE(decodeDataUri("data:,a%2").error.empty());
}

TEST(HeaderExamples, gltfWriterDraco) {
    // graph/io/GltfWriter.hpp
    const float corners[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    GltfWriter d;  // the same triangle, Draco-compressed
    const std::vector<std::uint32_t> corners3{0, 1, 2};
    GltfWriter::add(
        d.meshes,
        R"({"primitives": [)" +
            d.dracoPrimitive(3, {{.semantic = "POSITION", .data = corners, .components = 3, .quantizationBits = 14}},
                             corners3) +
            "]}");
    EXPECT_NE(d.text().find("KHR_draco_mesh_compression"), std::string::npos);
}
