// glTF skinning on the CPU side: JOINTS_0 and WEIGHTS_0 read and checked
// with their JSON pointers, the scene's joint matrices for a two-joint chain
// and a vertex posed by them, against numbers worked by hand, and the
// grouping box of a posed object.

#include "graph/animation/Skinning.hpp"
#include "graph/grouping/GroupingNodes.hpp"
#include "graph/io/ModelLoader.hpp"

#include "../support/GltfFile.hpp"
#include "../support/TempDir.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using namespace arcomp;
using arcomp::test::GltfFile;
using arcomp::test::TempDir;

namespace {

constexpr int kUnsignedByte = 5121, kUnsignedShort = 5123;

// The support file's triangle on node "body", skinned by joints "hip" and
// "knee" (nodes 1 and 2); accessor 2 is JOINTS_0, 3 WEIGHTS_0.
GltfFile skinnedTriangle(const std::vector<std::uint8_t>& joints, const std::vector<float>& weights) {
    GltfFile f;
    f.nodes =
        R"([{"name": "body", "mesh": 0, "skin": 0, "children": [1]}, {"name": "hip", "children": [2]}, {"name": "knee"}])";
    f.skins = R"([{"name": "legs", "joints": [1, 2]}])";
    const int j = f.addBytes(joints.data(), joints.size() / 4, "VEC4", kUnsignedByte);
    const int w = f.add(weights, "VEC4");
    f.attributes = R"(, "JOINTS_0": )" + std::to_string(j) + R"(, "WEIGHTS_0": )" + std::to_string(w);
    return f;
}

LoadedModel load(const GltfFile& f, Scene& scene) {
    TempDir dir;
    return loadModel(dir.write("model.gltf", f.json()), scene, scene.root());
}

NodeId firstMesh(const Scene& scene) {
    for (NodeId n = 0; n < scene.nodeCount(); ++n)
        if (scene.kind(n) == NodeKind::Mesh) return n;
    return kNoNode;
}

void expectSkinRejected(const GltfFile& f, const std::string& where, const std::string& reasonPart) {
    TempDir dir;
    Scene scene;
    try {
        loadModel(dir.write("bad.gltf", f.json()), scene, scene.root());
        ADD_FAILURE() << "loaded but should have been rejected at " << where;
    } catch (const ModelError& e) {
        EXPECT_EQ(e.where, where) << e.what();
        EXPECT_NE(e.reason.find(reasonPart), std::string::npos) << e.what();
    }
}

void expectMatrix(const glm::mat4& got, const glm::mat4& want) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(got[c][r], want[c][r], 1e-5f) << "column " << c << " row " << r;
}

}  // namespace

TEST(SkinInfluences, jointsAndWeightsAreReadAndAJointWithoutWeightBecomesZero) {
    Scene scene;
    const LoadedModel m =
        load(skinnedTriangle({0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0}, {0.25f, 0.75f, 0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0}),
             scene);
    EXPECT_TRUE(m.warnings.empty()) << m.warnings.front();
    const NodeId mesh = firstMesh(scene);
    ASSERT_NE(mesh, kNoNode);
    const MeshPart& part = scene.meshPart(mesh);
    ASSERT_NE(part.skin, kNoSkin);
    const Geometry& g = scene.geometry(part.geometry);
    ASSERT_TRUE(g.hasSkinInfluences());
    EXPECT_EQ(g.joints[0], glm::u16vec4(0, 1, 0, 0));
    EXPECT_EQ(g.weights[0], glm::vec4(0.25f, 0.75f, 0, 0));
    EXPECT_EQ(g.joints[1], glm::u16vec4(1, 0, 0, 0));  // the second 1 had no weight
    EXPECT_EQ(g.joints[2], glm::u16vec4(1, 0, 0, 0));
    ASSERT_EQ(scene.skinJoints(part.skin).size(), 2u);
    EXPECT_EQ(scene.name(scene.skinJoints(part.skin)[0]), "hip");
    EXPECT_EQ(scene.name(scene.skinJoints(part.skin)[1]), "knee");
}

TEST(SkinInfluences, normalizedShortWeightsReadAsFractions) {
    GltfFile f = skinnedTriangle({0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0}, {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0});
    const std::uint16_t shorts[12] = {16384, 49151, 0, 0, 65535, 0, 0, 0, 0, 65535, 0, 0};
    const int w = f.addBytes(shorts, 3, "VEC4", kUnsignedShort, true);
    f.attributes = R"(, "JOINTS_0": 2, "WEIGHTS_0": )" + std::to_string(w);
    Scene scene;
    load(f, scene);
    const Geometry& g = scene.geometry(scene.meshPart(firstMesh(scene)).geometry);
    EXPECT_NEAR(g.weights[0].x, 0.25f, 1e-4f);
    EXPECT_NEAR(g.weights[0].y, 0.75f, 1e-4f);
    EXPECT_EQ(g.weights[1], glm::vec4(1, 0, 0, 0));
    EXPECT_EQ(g.joints[2], glm::u16vec4(0, 1, 0, 0));
}

TEST(SkinInfluences, weightsAreRescaledToSumToOneAndOnlyAFarSumIsReported) {
    Scene near;
    const LoadedModel quiet = load(
        skinnedTriangle({0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0}, {0.5f, 0.4999f, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}), near);
    EXPECT_TRUE(quiet.warnings.empty()) << quiet.warnings.front();
    const Geometry& g = near.geometry(near.meshPart(firstMesh(near)).geometry);
    EXPECT_NEAR(g.weights[0].x + g.weights[0].y, 1.0f, 1e-6f);

    Scene far;
    const LoadedModel loud = load(
        skinnedTriangle({0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0}, {0.4f, 0.4f, 0, 0, 1, 0, 0, 0, 0.3f, 0.3f, 0, 0}), far);
    ASSERT_EQ(loud.warnings.size(), 1u);
    EXPECT_EQ(loud.warnings[0],
              "/meshes/0/primitives/0/attributes/WEIGHTS_0: the weights of 2 vertices (the first vertex 0) "
              "do not sum to 1; rescaled so they do");
    const Geometry& h = far.geometry(far.meshPart(firstMesh(far)).geometry);
    EXPECT_NEAR(h.weights[0].x, 0.5f, 1e-6f);
    EXPECT_NEAR(h.weights[2].y, 0.5f, 1e-6f);
}

TEST(SkinInfluences, badInfluencesAreRejectedWithTheirPointer) {
    const std::vector<std::uint8_t> joints{0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0};
    const std::vector<float> weights{0.5f, 0.5f, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
    expectSkinRejected(skinnedTriangle({0, 2, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0}, weights),
                       "/meshes/0/primitives/0/attributes/JOINTS_0",
                       "vertex 0 uses joint 2, but skin 0 'legs' of /nodes/0 has 2 joints");
    expectSkinRejected(skinnedTriangle(joints, {0.5f, 0.5f, 0, 0, 1, -0.5f, 0, 0, 1, 0, 0, 0}),
                       "/meshes/0/primitives/0/attributes/WEIGHTS_0", "vertex 1 has a negative weight");
    expectSkinRejected(skinnedTriangle(joints, {0.5f, 0.5f, 0, 0, 1, 0, 0, 0}),
                       "/meshes/0/primitives/0/attributes/WEIGHTS_0", "has 2 elements, POSITION has 3");

    GltfFile floatJoints = skinnedTriangle(joints, weights);
    const int j = floatJoints.add({0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0}, "VEC4");
    floatJoints.attributes = R"(, "JOINTS_0": )" + std::to_string(j) + R"(, "WEIGHTS_0": 3)";
    expectSkinRejected(floatJoints, "/accessors/" + std::to_string(j) + "/componentType",
                       "not allowed for /meshes/0/primitives/0/attributes/JOINTS_0");

    GltfFile rawBytes = skinnedTriangle(joints, weights);
    const std::uint8_t bytes[12] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0};
    const int w = rawBytes.addBytes(bytes, 3, "VEC4", kUnsignedByte);
    rawBytes.attributes = R"(, "JOINTS_0": 2, "WEIGHTS_0": )" + std::to_string(w);
    expectSkinRejected(rawBytes, "/accessors/" + std::to_string(w) + "/normalized", "weights must be normalized");

    GltfFile alone = skinnedTriangle(joints, weights);
    alone.attributes = R"(, "JOINTS_0": 2)";
    expectSkinRejected(alone, "/meshes/0/primitives/0/attributes", "has JOINTS_0 without WEIGHTS_0");
}

TEST(SkinInfluences, aVertexWithoutWeightLeavesThePrimitiveUnskinned) {
    Scene scene;
    const LoadedModel m =
        load(skinnedTriangle({0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0}, {0.5f, 0.5f, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0}), scene);
    ASSERT_EQ(m.warnings.size(), 2u);
    EXPECT_EQ(m.warnings[0],
              "/meshes/0/primitives/0/attributes/WEIGHTS_0: 1 vertices (the first vertex 1) have no weight on "
              "any joint; the primitive is not skinned");
    EXPECT_EQ(m.warnings[1],
              "/meshes/0/primitives/0: skinned by skin 0 'legs' (/nodes/0) but has no skin influences to "
              "pose it; drawn in its bind pose");
    EXPECT_EQ(scene.meshPart(firstMesh(scene)).skin, kNoSkin);
}

TEST(SkinInfluences, aSkinWithMoreJointsThanADrawTakesLeavesTheMeshInBindPose) {
    GltfFile f = skinnedTriangle({0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0}, {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0});
    std::string nodes = R"([{"name": "body", "mesh": 0, "skin": 0, "children": [1)";
    std::string joints;
    for (std::size_t n = 1; n <= kMaxJointsPerDraw + 1; ++n) {
        if (n > 1) nodes += ", " + std::to_string(n);
        joints += (n > 1 ? ", " : "") + std::to_string(n);
    }
    nodes += "]}";
    for (std::size_t n = 1; n <= kMaxJointsPerDraw + 1; ++n) nodes += R"(, {"name": "j)" + std::to_string(n) + "\"}";
    f.nodes = nodes + "]";
    f.skins = R"([{"name": "many", "joints": [)" + joints + "]}]";
    Scene scene;
    const LoadedModel m = load(f, scene);
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_EQ(
        m.warnings[0],
        "/nodes/0: skin 0 'many' has 65 joints, more than the 64 arcomp skins in one draw; drawn in its bind pose");
    EXPECT_EQ(scene.meshPart(firstMesh(scene)).skin, kNoSkin);
}

// A chain: "hip" at (0, -1, 0), "knee" below it at (0, 1, 0) from the hip and
// turned 90 degrees about Z; bound with the knee at the origin, unturned.
// The mesh node stands at (2, 0, 0), which skinning must undo.
struct Chain {
    Scene scene;
    NodeId mesh, hip, knee;
    std::uint32_t skin;

    Chain() {
        const NodeId body = scene.addTransform(scene.root(), glm::translate(glm::mat4(1.0f), {2, 0, 0}), "body");
        hip = scene.addTransform(scene.root(), glm::translate(glm::mat4(1.0f), {0, -1, 0}), "hip");
        knee = scene.addTransform(
            hip, glm::rotate(glm::translate(glm::mat4(1.0f), {0, 1, 0}), glm::radians(90.0f), {0, 0, 1}), "knee");
        Geometry g;
        g.positions = {{1, 1, 0}, {0, 0, 0}, {0, 1, 0}};
        g.indices = {0, 1, 2};
        g.joints = {{0, 1, 0, 0}, {0, 0, 0, 0}, {1, 0, 0, 0}};
        g.weights = {{0.5f, 0.5f, 0, 0}, {1, 0, 0, 0}, {1, 0, 0, 0}};
        g.finalize();
        const NodeId joints[2] = {hip, knee};
        const glm::mat4 inverseBinds[2] = {glm::translate(glm::mat4(1.0f), {0, 1, 0}), glm::mat4(1.0f)};
        skin = scene.addSkin(body, joints, inverseBinds);
        mesh = scene.addMesh(body, {scene.addGeometry(std::move(g)), scene.addMaterial({}), skin});
        scene.update();
    }
};

TEST(SkinJoints, jointMatricesOfATwoJointChainAreTheHandWorkedOnes) {
    Chain c;
    const auto m = c.scene.jointMatrices(c.skin);
    ASSERT_EQ(m.size(), 2u);
    // hip: T(-2,0,0) * T(0,-1,0) * T(0,1,0) = T(-2,0,0)
    expectMatrix(m[0], glm::mat4({1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {-2, 0, 0, 1}));
    // knee: T(-2,0,0) * T(0,-1,0) * T(0,1,0) * Rz(90) = T(-2,0,0) * Rz(90); x goes to y, y to -x
    expectMatrix(m[1], glm::mat4({0, 1, 0, 0}, {-1, 0, 0, 0}, {0, 0, 1, 0}, {-2, 0, 0, 1}));

    // Turning the knee back moves only its matrix.
    c.scene.setLocal(c.knee, glm::translate(glm::mat4(1.0f), {0, 1, 0}));
    c.scene.update();
    expectMatrix(c.scene.jointMatrices(c.skin)[1], glm::translate(glm::mat4(1.0f), {-2, 0, 0}));
}

TEST(SkinJoints, aPosedVertexIsTheWeightedSumOfItsJointsAndIgnoresTheMeshNodesPlace) {
    Chain c;
    const Geometry& g = c.scene.geometry(c.scene.meshPart(c.mesh).geometry);
    const std::vector<glm::vec3> posed = skinPositions(g, c.scene.jointMatrices(c.skin));
    // (1,1,0): half by the hip, to (-1,1,0); half by the knee, Rz(90) to
    // (-1,1,0) then to (-3,1,0); the mean is (-2,1,0) in the mesh's space.
    EXPECT_NEAR(posed[0].x, -2.0f, 1e-5f);
    EXPECT_NEAR(posed[0].y, 1.0f, 1e-5f);
    EXPECT_NEAR(posed[0].z, 0.0f, 1e-5f);
    // (0,1,0) on the knee alone: Rz(90) gives (-1,0,0).
    EXPECT_NEAR(posed[2].x, -3.0f, 1e-5f);
    EXPECT_NEAR(posed[2].y, 0.0f, 1e-5f);
    // In the world the mesh node's (2,0,0) cancels: the joints alone place it.
    const glm::vec3 world = glm::vec3(c.scene.world(c.mesh) * glm::vec4(posed[0], 1.0f));
    EXPECT_NEAR(world.x, 0.0f, 1e-5f);
    EXPECT_NEAR(world.y, 1.0f, 1e-5f);
    c.scene.setLocal(c.scene.parent(c.mesh), glm::translate(glm::mat4(1.0f), {7, 3, 0}));
    c.scene.update();
    const glm::vec3 moved =
        glm::vec3(c.scene.world(c.mesh) * glm::vec4(skinPositions(g, c.scene.jointMatrices(c.skin))[0], 1.0f));
    EXPECT_NEAR(moved.x, 0.0f, 1e-5f);
    EXPECT_NEAR(moved.y, 1.0f, 1e-5f);
}

// The grouping tree's box of a skinned object is where its joints put it:
// here the one joint stands 5 units along x from the mesh node, so the bind
// pose's box (around the origin) would miss the drawn square entirely.
TEST(SkinJoints, aSkinnedObjectsGroupingBoxHoldsItsPosedMesh) {
    Scene scene;
    Geometry g;
    g.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    g.indices = {0, 1, 2, 0, 2, 3};
    g.joints.assign(4, {0, 0, 0, 0});
    g.weights.assign(4, {1, 0, 0, 0});
    g.finalize();
    const NodeId place = scene.addTransform(scene.root(), glm::mat4(1.0f));
    const NodeId joint[1] = {scene.addTransform(scene.root(), glm::translate(glm::mat4(1.0f), {5, 0, 0}))};
    const glm::mat4 bind[1] = {glm::mat4(1.0f)};
    const std::uint32_t skin = scene.addSkin(place, joint, bind);
    const NodeId mesh = scene.addMesh(place, {scene.addGeometry(std::move(g)), scene.addMaterial({}), skin});
    const NodeId meshes[1] = {mesh};
    fitPosedBounds(scene, meshes, {});
    const Box box = groupingItemOf(scene, place).box;
    for (const glm::vec3& p : skinPositions(scene.geometry(scene.meshPart(mesh).geometry), scene.jointMatrices(skin))) {
        EXPECT_GE(p.x, box.min.x);
        EXPECT_LE(p.x, box.max.x);
        EXPECT_GE(p.y, box.min.y);
        EXPECT_LE(p.y, box.max.y);
    }
    EXPECT_GT(box.min.x, 3.0f) << "the box is around the posed square, not the bind pose";
}
