// A config object's model animation: the config keys, the checks made once
// the model is loaded, and a station that plays it on the video's clock.

#include "graph/core/SelectPass.hpp"
#include "runtime/config/ConfigError.hpp"
#include "runtime/config/StationConfig.hpp"
#include "runtime/gl/GlContext.hpp"
#include "runtime/station/ReplayInput.hpp"
#include "runtime/station/SceneFile.hpp"
#include "runtime/station/Station.hpp"
#include "video/sources/TestPatternSource.hpp"

#include "../support/ConfigIssues.hpp"
#include "../support/GltfFile.hpp"
#include "../support/TempDir.hpp"

#include <gtest/gtest.h>

using namespace arcomp;
using arcomp::test::configIssues;
using arcomp::test::describe;
using arcomp::test::GltfFile;
using arcomp::test::hasIssue;
using arcomp::test::slidingTriangle;
using arcomp::test::TempDir;

namespace {

std::string objectYaml(const std::string& keys) {
    return "scene:\n  objects:\n    - name: walker\n      model: slide.gltf\n" + keys +
           "camera:\n  eye: [0, 0, 0]\n  target: [0, 0, -1]\n";
}

}  // namespace

TEST(ObjectAnimationConfig, readsAnimationLoopAndSpeed) {
    TempDir dir;
    dir.write("slide.gltf", slidingTriangle());
    const StationConfig cfg = loadStationConfig(
        dir.write("s.yaml", objectYaml("      animation: grow\n      loop: false\n      speed: 2.5\n")));
    const ObjectConfig& o = cfg.objects.at(0);
    EXPECT_EQ(o.animation, "grow");
    EXPECT_FALSE(o.animationLoop);
    EXPECT_FLOAT_EQ(o.animationSpeed, 2.5f);
    const StationConfig plain = loadStationConfig(dir.write("p.yaml", objectYaml("")));
    EXPECT_EQ(plain.objects.at(0).animation, "");
    EXPECT_TRUE(plain.objects.at(0).animationLoop);
    EXPECT_FLOAT_EQ(plain.objects.at(0).animationSpeed, 1.0f);
}

TEST(ObjectAnimationConfig, reportsMisplacedAndOutOfRangeKeys) {
    TempDir dir;
    dir.write("slide.gltf", slidingTriangle());
    const auto issues = configIssues(dir.write("bad.yaml", R"(scene:
  objects:
    - shape: box
      animation: slide
    - model: slide.gltf
      loop: false
    - model: slide.gltf
      animation: slide
      speed: -1
    - model: slide.gltf
      animation: [1, 2]
)"));
    EXPECT_TRUE(hasIssue(issues, 3, "objects[0].animation: only a model has animations")) << describe(issues);
    EXPECT_TRUE(hasIssue(issues, 5, "objects[1].loop: only with 'animation'")) << describe(issues);
    EXPECT_TRUE(hasIssue(issues, 9, "speed: -1 is out of range")) << describe(issues);
    EXPECT_TRUE(hasIssue(issues, 11, "animation: expected a text value")) << describe(issues);
}

TEST(ObjectAnimationConfig, anUnknownAnimationSkipsTheObjectNamingWhatTheModelHas) {
    TempDir dir;
    dir.write("slide.gltf", slidingTriangle());
    const StationConfig cfg = loadStationConfig(dir.write("s.yaml", objectYaml("      animation: jump\n")));
    World world;
    std::vector<std::string> warnings;
    buildScene(cfg, world, warnings);
    ASSERT_EQ(warnings.size(), 1u);
    const std::string& w = warnings[0];
    EXPECT_NE(w.find("s.yaml:3: object 'walker' skipped"), std::string::npos) << w;
    EXPECT_NE(w.find("slide.gltf' has no animation 'jump'; its animations: 0 'slide', 1 'grow'"), std::string::npos)
        << w;
    EXPECT_TRUE(world.animations.empty());
    EXPECT_EQ(world.scene.geometries().size(), 0u) << "nothing of the model may be placed";
    // An index past the end is refused the same way.
    std::vector<std::string> byIndex;
    World other;
    buildScene(loadStationConfig(dir.write("i.yaml", objectYaml("      animation: 2\n"))), other, byIndex);
    ASSERT_EQ(byIndex.size(), 1u);
    EXPECT_NE(byIndex[0].find("has no animation '2'"), std::string::npos) << byIndex[0];
}

TEST(ObjectAnimationConfig, anObjectWithoutAnimationKeyPlaysNone) {
    TempDir dir;
    dir.write("slide.gltf", slidingTriangle());
    World world;
    std::vector<std::string> warnings;
    buildScene(loadStationConfig(dir.write("s.yaml", objectYaml(""))), world, warnings);
    EXPECT_TRUE(warnings.empty());
    EXPECT_TRUE(world.animations.empty());
    EXPECT_EQ(world.scene.geometries().size(), 1u);
}

TEST(ObjectAnimationConfig, theNamedOrIndexedClipIsBoundWithItsOptions) {
    TempDir dir;
    dir.write("slide.gltf", slidingTriangle());
    World world;
    std::vector<std::string> warnings;
    buildScene(
        loadStationConfig(dir.write("s.yaml", objectYaml("      animation: 1\n      speed: 0.5\n      loop: false\n"))),
        world, warnings);
    EXPECT_TRUE(warnings.empty());
    ASSERT_EQ(world.animations.size(), 1u);
    const ObjectAnimation& a = world.animations[0];
    EXPECT_EQ(a.player.animation().clip.name, "grow");
    EXPECT_FALSE(a.player.options().loop);
    EXPECT_DOUBLE_EQ(a.player.options().speed, 0.5);
    EXPECT_EQ(world.scene.name(a.node), "walker");
    // The animated object's bound follows the pose after animateObjects.
    world.scene.update();
    const float rest = world.scene.worldBound(a.node).radius;
    animateObjects(world, 4.0);  // 2 clip seconds, held at the last key: scale 2
    EXPECT_NEAR(world.scene.worldBound(a.node).radius, 2.0f * rest, 1e-5f);
    // Its meshes count as moving: their holdouts are not baked for one pose.
    for (NodeId n = 0; n < world.scene.nodeCount(); ++n)
        if (world.scene.kind(n) == NodeKind::Mesh) {
            EXPECT_TRUE(movesOverTime(world, n));
        }
    EXPECT_FALSE(movesOverTime(world, world.scene.root()));
}

// Inside a grouping node the animated object is regrouped as a mover is:
// the grouping tree sees its new box (here twice the size, "grow" held at
// its last key).
TEST(ObjectAnimationConfig, anAnimatedObjectInAGroupingNodeHasItsBoxRefreshed) {
    TempDir dir;
    dir.write("slide.gltf", slidingTriangle());
    StationConfig cfg =
        loadStationConfig(dir.write("s.yaml", objectYaml("      animation: grow\n      loop: false\n")));
    ObjectConfig box;
    box.name = "box";
    box.shape = "box";
    box.position = {5.0f, 0.0f, 0.0f};
    cfg.objects.push_back(box);
    cfg.grouping.enabled = true;
    cfg.grouping.objects = true;
    World world;
    std::vector<std::string> warnings;
    buildScene(cfg, world, warnings);
    ASSERT_TRUE(warnings.empty()) << warnings[0];
    ASSERT_EQ(world.animations.size(), 1u);
    const ObjectAnimation& a = world.animations[0];
    ASSERT_NE(a.groupingNode, kNoNode);
    const GroupingNode& grouping = world.grouping.nodes[world.scene.payload(a.groupingNode)];
    ASSERT_EQ(grouping.objects.at(a.groupingObject), a.node);
    const glm::vec3 rest = grouping.tree.item(a.groupingObject).box.size();
    animateObjects(world, 5.0);
    const glm::vec3 grown = grouping.tree.item(a.groupingObject).box.size();
    EXPECT_NEAR(grown.x, 2.0f * rest.x, 1e-5f);
    EXPECT_NEAR(grown.y, 2.0f * rest.y, 1e-5f);
}

namespace {

StationConfig slidingStation(const std::filesystem::path& model, bool animated) {
    StationConfig cfg;
    cfg.file = "animated.yaml";
    ObjectConfig o;
    o.name = "slider";
    o.model = model;
    o.position = {0.0f, -0.5f, -4.0f};
    if (animated) o.animation = "slide";
    cfg.objects.push_back(o);
    cfg.camera.given = true;
    cfg.camera.eye = {0.0f, 0.0f, 0.0f};
    cfg.camera.target = {0.0f, 0.0f, -1.0f};
    cfg.compositing.compositor.backdropVideo = false;
    cfg.compositing.compositor.bakeCache = "none";  // leave the user's cache alone
    return cfg;
}

// Every frame of a 30 fps pattern replay, composited, read back.
std::vector<Image> replay(const StationConfig& cfg, int frames) {
    Station station(cfg, StationInput::fromReplay(std::make_unique<TestPatternSource>(
                                                      TestPatternOptions{.width = 160, .height = 120, .paced = false}),
                                                  30.0));
    std::vector<Image> out;
    for (int i = 0; i < frames; ++i) {
        EXPECT_TRUE(station.frame());
        out.push_back(station.compositedFrame().read());
    }
    return out;
}

}  // namespace

// Frame i is at video time i/30 s. The slide starts at the pose the file
// gives the node, so frame 0 matches the same model unanimated; later frames
// do not. Two runs give the same bytes frame for frame.
TEST(ObjectAnimationStation, playsOnVideoTimeAndReplaysIdentically) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    TempDir dir;
    const auto model = dir.write("slide.gltf", slidingTriangle());
    const int frames = 16;
    const std::vector<Image> first = replay(slidingStation(model, true), frames);
    const std::vector<Image> second = replay(slidingStation(model, true), frames);
    const std::vector<Image> still = replay(slidingStation(model, false), frames);
    for (int i = 0; i < frames; ++i) EXPECT_EQ(first[i].rgba, second[i].rgba) << "frame " << i;
    EXPECT_EQ(first[0].rgba, still[0].rgba);
    EXPECT_NE(first[15].rgba, still[15].rgba);  // half a second in: x = 0, not -1
    EXPECT_NE(first[8].rgba, still[8].rgba);
}
