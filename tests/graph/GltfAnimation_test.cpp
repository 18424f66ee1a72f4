// glTF animations and skins from generated files: a node that turns and
// slides, placed and played; every validation failure with its JSON pointer.

#include "graph/animation/AnimationPlayer.hpp"
#include "graph/io/ModelLoader.hpp"

#include "../support/GltfFile.hpp"
#include "../support/TempDir.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

using namespace arcomp;
using arcomp::test::GltfFile;
using arcomp::test::TempDir;

namespace {

// An animation with one sampler and one channel on node 0.
std::string oneChannel(int input, int output, const std::string& path, const std::string& interpolation = "LINEAR",
                       int node = 0) {
    return R"([{"name": "spin", "samplers": [{"input": )" + std::to_string(input) + R"(, "output": )" +
           std::to_string(output) + R"(, "interpolation": ")" + interpolation +
           R"("}], "channels": [{"sampler": 0, "target": {"node": )" + std::to_string(node) + R"(, "path": ")" + path +
           R"("}}]}])";
}

void expectAnimationRejected(const GltfFile& f, const std::string& where, const std::string& reasonPart) {
    TempDir dir;
    const auto file = dir.write("bad.gltf", f.json());
    Scene scene;
    const std::size_t before = scene.nodeCount();
    try {
        loadModel(file, scene, scene.root());
        ADD_FAILURE() << "loaded but should have been rejected at " << where;
    } catch (const ModelError& e) {
        EXPECT_EQ(e.where, where) << e.what();
        EXPECT_NE(e.reason.find(reasonPart), std::string::npos) << e.what();
    }
    EXPECT_EQ(scene.nodeCount(), before) << "a rejected model must leave the scene untouched";
}

LoadedModel loadText(const GltfFile& f, Scene& scene) {
    TempDir dir;
    return loadModel(dir.write("model.gltf", f.json()), scene, scene.root());
}

glm::vec4 turnAboutZ(float degrees) {
    const float half = glm::radians(degrees) / 2.0f;
    return {0.0f, 0.0f, std::sin(half), std::cos(half)};
}

void expectSameMatrix(const glm::mat4& got, const glm::mat4& want) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(got[c][r], want[c][r], 1e-5f) << "column " << c << " row " << r;
}

}  // namespace

// The spinner is scaled ×2 at rest and, over 2 s, slides from x = 0 to x = 4
// and turns from 0° through 90° (at 1 s) to 180° about Z. At 0.5 s: x = 1,
// 45°; at 1 s: x = 2, 90°.
TEST(GltfAnimation, aNodeTurnsAndSlidesWhenPlayed) {
    GltfFile f;
    f.nodes = R"([{"name": "spinner", "mesh": 0, "scale": [2, 2, 2]}])";
    const int times = f.add({0, 2}, "SCALAR");
    const int slide = f.add({0, 0, 0, 4, 0, 0}, "VEC3");
    // 180° in one step would be as near one way round as the other.
    const int turnTimes = f.add({0, 1, 2}, "SCALAR");
    const glm::vec4 a = turnAboutZ(0), b = turnAboutZ(90), c = turnAboutZ(180);
    const int turn = f.add({a.x, a.y, a.z, a.w, b.x, b.y, b.z, b.w, c.x, c.y, c.z, c.w}, "VEC4");
    f.animations = R"([{"name": "spin", "samplers": [{"input": )" + std::to_string(times) + R"(, "output": )" +
                   std::to_string(slide) + R"(}, {"input": )" + std::to_string(turnTimes) + R"(, "output": )" +
                   std::to_string(turn) +
                   R"(}], "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}},
                                       {"sampler": 1, "target": {"node": 0, "path": "rotation"}}]}])";
    Scene scene;
    LoadedModel m = loadText(f, scene);
    ASSERT_EQ(m.animations.size(), 1u);
    const ModelAnimation& anim = m.animations[0];
    EXPECT_EQ(anim.clip.name, "spin");
    EXPECT_FLOAT_EQ(anim.clip.duration(), 2.0f);
    ASSERT_EQ(anim.nodes.size(), 1u);  // two channels, one node
    const NodeId node = anim.nodes[0].node;
    EXPECT_EQ(scene.name(node), "spinner");
    EXPECT_EQ(anim.nodes[0].rest.scale, glm::vec3(2.0f));
    scene.update();
    const Sphere local = scene.geometry(0).bound;
    AnimationPlayer player(anim);
    for (const auto& [seconds, x, degrees] : {std::tuple{0.0, 0.0f, 0.0f}, {0.5, 1.0f, 45.0f}, {1.0, 2.0f, 90.0f}}) {
        SCOPED_TRACE(seconds);
        player.apply(scene, seconds);
        scene.update();
        const glm::mat4 want = glm::scale(
            glm::rotate(glm::translate(glm::mat4(1.0f), {x, 0, 0}), glm::radians(degrees), {0, 0, 1}), glm::vec3(2.0f));
        expectSameMatrix(scene.world(node), want);
        // The bound moved and turned with the node: centred on the turned,
        // scaled triangle's centre, twice its radius.
        const glm::vec3 centre = glm::vec3(want * glm::vec4(local.center, 1.0f));
        const Sphere& bound = scene.worldBound(node);
        EXPECT_NEAR(bound.center.x, centre.x, 1e-5f);
        EXPECT_NEAR(bound.center.y, centre.y, 1e-5f);
        EXPECT_NEAR(bound.center.z, centre.z, 1e-5f);
        EXPECT_NEAR(bound.radius, 2.0f * local.radius, 1e-5f);
        EXPECT_NEAR(scene.bound().center.x, centre.x, 1e-5f);
    }
}

TEST(GltfAnimation, authoredTrsIsKeptBesideTheMatrix) {
    TempDir dir;
    GltfFile f;
    f.nodes = R"([{"mesh": 0, "translation": [1, 2, 3], "rotation": [0, 0, 1, 0], "scale": [1, 1, 5], "children": [1]},
                 {"matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 7,0,0,1]}])";
    const ParsedModel p = parseGltf(dir.write("trs.gltf", f.json()));
    ASSERT_EQ(p.nodes.size(), 2u);
    ASSERT_TRUE(p.nodes[0].trs);
    EXPECT_EQ(p.nodes[0].trs->translation, glm::vec3(1, 2, 3));
    EXPECT_FLOAT_EQ(p.nodes[0].trs->rotation.z, 1.0f);
    EXPECT_EQ(p.nodes[0].trs->scale, glm::vec3(1, 1, 5));
    expectSameMatrix(p.nodes[0].trs->matrix(), p.nodes[0].local);
    EXPECT_FALSE(p.nodes[1].trs);  // a matrix node has no TRS to animate
}

TEST(GltfAnimation, stepAndCubicSplineSamplersAreRead) {
    GltfFile f;
    const int times = f.add({0, 1}, "SCALAR");
    const int steps = f.add({1, 1, 1, 3, 3, 3}, "VEC3");
    const int cubic = f.add({0, 0, 0, 0, 0, 0, 9, 9, 9, /**/ 9, 9, 9, 1, 2, 3, 0, 0, 0}, "VEC3");
    f.nodes = R"([{"mesh": 0, "children": [1]}, {"name": "child"}])";
    f.animations =
        R"([{"samplers": [{"input": )" + std::to_string(times) + R"(, "output": )" + std::to_string(steps) +
        R"(, "interpolation": "STEP"}, {"input": )" + std::to_string(times) + R"(, "output": )" +
        std::to_string(cubic) +
        R"(, "interpolation": "CUBICSPLINE"}], "channels": [{"sampler": 0, "target": {"node": 0, "path": "scale"}},
                      {"sampler": 1, "target": {"node": 1, "path": "translation"}}]}])";
    Scene scene;
    const LoadedModel m = loadText(f, scene);
    ASSERT_EQ(m.animations.size(), 1u);
    const AnimationClip& clip = m.animations[0].clip;
    EXPECT_EQ(clip.name, "animation0");  // unnamed in the file
    ASSERT_EQ(clip.channels.size(), 2u);
    EXPECT_EQ(clip.channels[0].interpolation, Interpolation::Step);
    EXPECT_EQ(clip.channels[1].interpolation, Interpolation::CubicSpline);
    ASSERT_EQ(clip.channels[1].values.size(), 6u);
    EXPECT_EQ(sample(clip.channels[0], 0.5f), glm::vec4(1, 1, 1, 0));
    EXPECT_EQ(sample(clip.channels[1], 1.0f), glm::vec4(1, 2, 3, 0));
    EXPECT_EQ(m.animations[0].nodes.size(), 2u);
    EXPECT_EQ(scene.name(m.animations[0].nodes[clip.channels[1].target].node), "child");
}

TEST(GltfAnimation, normalizedIntegerRotationsAreAllowed) {
    GltfFile f;
    const int times = f.add({0, 1}, "SCALAR");
    const std::int16_t q[8] = {0, 0, 0, 32767, 0, 0, 32767, 0};
    const int rot = f.addBytes(q, 2, "VEC4", GltfWriter::kShort, true);
    f.animations = oneChannel(times, rot, "rotation");
    Scene scene;
    const LoadedModel m = loadText(f, scene);
    ASSERT_EQ(m.animations.size(), 1u);
    EXPECT_NEAR(sample(m.animations[0].clip.channels[0], 1.0f).z, 1.0f, 1e-6f);
    const int raw = f.addBytes(q, 2, "VEC4", 5122, false);
    f.animations = oneChannel(times, raw, "rotation");
    expectAnimationRejected(f, "/accessors/" + std::to_string(raw) + "/normalized", "must be normalized");
}

TEST(GltfAnimation, samplerInputMustBeFloatScalarTimesThatIncrease) {
    GltfFile f;
    const int out = f.add({0, 0, 0, 1, 1, 1}, "VEC3");
    const int vec = f.add({0, 1, 2, 3, 4, 5}, "VEC3");
    f.animations = oneChannel(vec, out, "translation");
    expectAnimationRejected(f, "/accessors/" + std::to_string(vec) + "/type",
                            "expected SCALAR (used by /animations/0/samplers/0/input)");
    const std::uint16_t shorts[2] = {0, 1};
    const int ints = f.addBytes(shorts, 2, "SCALAR", 5123);
    f.animations = oneChannel(ints, out, "translation");
    expectAnimationRejected(f, "/accessors/" + std::to_string(ints) + "/componentType",
                            "not allowed for /animations/0/samplers/0/input");
    const int flat = f.add({0, 0}, "SCALAR");
    f.animations = oneChannel(flat, out, "translation");
    expectAnimationRejected(f, "/animations/0/samplers/0/input", "key times must increase: key 1");
    const int falling = f.add({1, 0.5f}, "SCALAR");
    f.animations = oneChannel(falling, out, "translation");
    expectAnimationRejected(f, "/animations/0/samplers/0/input", "key times must increase");
    f.animations = oneChannel(99, out, "translation");
    expectAnimationRejected(f, "/animations/0/samplers/0/input", "accessor 99 does not exist");
}

TEST(GltfAnimation, outputCountMustMatchTheKeysThreeTimesForCubicSpline) {
    GltfFile f;
    const int times = f.add({0, 1}, "SCALAR");
    const int three = f.add({0, 0, 0, 1, 1, 1, 2, 2, 2}, "VEC3");
    f.animations = oneChannel(times, three, "translation");
    expectAnimationRejected(f, "/animations/0/samplers/0/output", "has 3 elements; expected 2 (2 key times)");
    const int two = f.add({0, 0, 0, 1, 1, 1}, "VEC3");
    f.animations = oneChannel(times, two, "scale", "CUBICSPLINE");
    expectAnimationRejected(f, "/animations/0/samplers/0/output",
                            "has 2 elements; expected 6 (2 key times × 3 for CUBICSPLINE)");
    f.animations = oneChannel(times, two, "scale", "BEZIER");
    expectAnimationRejected(f, "/animations/0/samplers/0/interpolation", "unknown interpolation 'BEZIER'");
}

TEST(GltfAnimation, outputTypeFollowsThePath) {
    GltfFile f;
    const int times = f.add({0, 1}, "SCALAR");
    const int vec4 = f.add({0, 0, 0, 1, 0, 0, 0, 1}, "VEC4");
    const int vec3 = f.add({0, 0, 0, 1, 1, 1}, "VEC3");
    f.animations = oneChannel(times, vec4, "translation");
    expectAnimationRejected(f, "/accessors/" + std::to_string(vec4) + "/type",
                            "is VEC4, expected VEC3 (used by /animations/0/samplers/0/output)");
    f.animations = oneChannel(times, vec3, "rotation");
    expectAnimationRejected(f, "/accessors/" + std::to_string(vec3) + "/type", "is VEC3, expected VEC4");
    const std::uint8_t bytes[6] = {0, 0, 0, 1, 1, 1};
    const int byteScale = f.addBytes(bytes, 2, "VEC3", 5121, true);
    f.animations = oneChannel(times, byteScale, "scale");
    expectAnimationRejected(f, "/accessors/" + std::to_string(byteScale) + "/componentType", "not allowed");
    const int zero = f.add({0, 0, 0, 0, 0, 0, 0, 1}, "VEC4");
    f.animations = oneChannel(times, zero, "rotation");
    expectAnimationRejected(f, "/animations/0/samplers/0/output", "key 0 is not a rotation");
}

TEST(GltfAnimation, channelsMustTargetExistingNodesWithoutAMatrix) {
    GltfFile f;
    const int times = f.add({0, 1}, "SCALAR");
    const int out = f.add({0, 0, 0, 1, 1, 1}, "VEC3");
    f.animations = oneChannel(times, out, "translation", "LINEAR", 5);
    expectAnimationRejected(f, "/animations/0/channels/0/target/node", "node 5 does not exist (1 nodes)");
    f.nodes = R"([{"mesh": 0, "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}])";
    f.animations = oneChannel(times, out, "translation");
    expectAnimationRejected(f, "/animations/0/channels/0/target/node", "node 0 gives a matrix");
    f.nodes = R"([{"mesh": 0}])";
    f.animations = R"([{"samplers": [{"input": )" + std::to_string(times) + R"(, "output": )" + std::to_string(out) +
                   R"(}], "channels": [{"sampler": 1, "target": {"node": 0, "path": "translation"}}]})" + "]";
    expectAnimationRejected(f, "/animations/0/channels/0/sampler", "sampler 1 does not exist (1 samplers)");
    f.animations = R"([{"samplers": [{"input": )" + std::to_string(times) + R"(, "output": )" + std::to_string(out) +
                   R"(}], "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}},
                                       {"sampler": 0, "target": {"node": 0, "path": "translation"}}]})" +
                   "]";
    expectAnimationRejected(f, "/animations/0/channels/1", "a second channel for the translation of node 0");
}

TEST(GltfAnimation, morphWeightsAreSkippedWithAWarningNamingTheAnimation) {
    GltfFile f;
    const int times = f.add({0, 1}, "SCALAR");
    const int weights = f.add({0, 1}, "SCALAR");
    const int out = f.add({0, 0, 0, 1, 1, 1}, "VEC3");
    f.animations = R"([{"name": "blink", "samplers": [{"input": )" + std::to_string(times) + R"(, "output": )" +
                   std::to_string(weights) + R"(}, {"input": )" + std::to_string(times) + R"(, "output": )" +
                   std::to_string(out) +
                   R"(}], "channels": [{"sampler": 0, "target": {"node": 0, "path": "weights"}},
                                       {"sampler": 1, "target": {"node": 0, "path": "scale"}}]}])";
    Scene scene;
    const LoadedModel m = loadText(f, scene);
    ASSERT_EQ(m.animations.size(), 1u);
    ASSERT_EQ(m.animations[0].clip.channels.size(), 1u);
    EXPECT_EQ(m.animations[0].clip.channels[0].path, AnimationPath::Scale);
    bool warned = false;
    for (const std::string& w : m.warnings)
        warned |= w.find("/animations/0/channels/0") != std::string::npos && w.find("'blink'") != std::string::npos &&
                  w.find("weights") != std::string::npos;
    EXPECT_TRUE(warned);
}

TEST(GltfSkin, jointsAndInverseBindMatricesAreKeptAndTheMeshDrawnInBindPose) {
    GltfFile f;
    f.nodes =
        R"([{"name": "body", "mesh": 0, "skin": 0, "children": [1]}, {"name": "hip", "children": [2]}, {"name": "knee"}])";
    std::vector<float> ibm;
    for (int j = 0; j < 2; ++j) {
        const glm::mat4 m = glm::translate(glm::mat4(1.0f), {0, -float(j + 1), 0});
        for (int e = 0; e < 16; ++e) ibm.push_back(m[e / 4][e % 4]);
    }
    const int matrices = f.add(ibm, "MAT4");
    f.skins = R"([{"name": "legs", "joints": [1, 2], "skeleton": 1, "inverseBindMatrices": )" +
              std::to_string(matrices) + "}]";
    Scene scene;
    const LoadedModel m = loadText(f, scene);
    ASSERT_EQ(m.skins.size(), 1u);
    const Skin& skin = m.skins[0];
    EXPECT_EQ(skin.name, "legs");
    ASSERT_EQ(skin.joints.size(), 2u);
    EXPECT_EQ(scene.name(skin.joints[0]), "hip");
    EXPECT_EQ(scene.name(skin.joints[1]), "knee");
    EXPECT_EQ(scene.name(skin.skeleton), "hip");
    ASSERT_EQ(skin.users.size(), 1u);
    EXPECT_EQ(scene.name(skin.users[0]), "body");
    EXPECT_FLOAT_EQ(skin.inverseBindMatrices[1][3].y, -2.0f);
    bool warned = false;
    // The mesh has no JOINTS_0 and WEIGHTS_0 to skin it with.
    for (const std::string& w : m.warnings)
        warned |= w == "/meshes/0/primitives/0: skinned by skin 0 'legs' (/nodes/0) but has no skin influences to pose "
                       "it; drawn in its bind pose";
    EXPECT_TRUE(warned);
}

TEST(GltfSkin, badSkinsAreRejectedWithTheirPointer) {
    GltfFile f;
    f.nodes = R"([{"mesh": 0, "skin": 0, "children": [1]}, {}])";
    f.skins = R"([{"joints": [1, 4]}])";
    expectAnimationRejected(f, "/skins/0/joints/1", "node 4 does not exist");
    f.skins = R"([{"joints": [1], "skeleton": 9}])";
    expectAnimationRejected(f, "/skins/0/skeleton", "node 9 does not exist");
    f.nodes = R"([{"mesh": 0, "skin": 3, "children": [1]}, {}])";
    f.skins = R"([{"joints": [1]}])";
    expectAnimationRejected(f, "/nodes/0/skin", "skin 3 does not exist (1 skins)");
    f.nodes = R"([{"mesh": 0, "skin": 0, "children": [1]}, {}, {}])";
    const int one = f.add(std::vector<float>(16, 0.0f), "MAT4");
    f.skins = R"([{"joints": [1, 2], "inverseBindMatrices": )" + std::to_string(one) + "}]";
    expectAnimationRejected(f, "/skins/0/inverseBindMatrices", "has 1 matrices for 2 joints");
}
