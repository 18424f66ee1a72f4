// The station config's grouping section and the grouped scene it builds.

#include "graph/core/SelectPass.hpp"
#include "graph/scenes/ForestExperiment.hpp"
#include "runtime/config/ConfigError.hpp"
#include "runtime/config/StationConfig.hpp"
#include "runtime/station/SceneFile.hpp"

#include "../support/TempDir.hpp"

#include <gtest/gtest.h>

using namespace arcomp;
using arcomp::test::TempDir;

namespace {

const char* const kGroupingScene = R"(scene:
  objects:
    - shape: box
      size: [100, 100, 100]
)";

}  // namespace

TEST(GroupingConfig, absentSectionGroupsNothing) {
    TempDir dir;
    const StationConfig cfg = loadStationConfig(dir.write("a.yaml", kGroupingScene));
    EXPECT_FALSE(cfg.grouping.enabled);
    SceneFile f = loadSceneFile(dir.write("b.yaml", kGroupingScene));
    EXPECT_TRUE(f.world.grouping.nodes.empty());
    for (NodeId n = 0; n < f.world.scene.nodeCount(); ++n) EXPECT_NE(f.world.scene.kind(n), NodeKind::Grouping);
}

TEST(GroupingConfig, defaultsAreThePapersParameters) {
    TempDir dir;
    const StationConfig cfg = loadStationConfig(dir.write("a.yaml", std::string(kGroupingScene) + "grouping: {}\n"));
    EXPECT_TRUE(cfg.grouping.enabled);
    const GroupingParams& p = cfg.grouping.params;
    EXPECT_EQ(p.l0, 5000.0f);
    EXPECT_EQ(p.alphaP, 0.1f);
    EXPECT_EQ(p.alphaS, 2000.0f);
    EXPECT_EQ(p.alphaC, 2000.0f);
    EXPECT_EQ(p.alphaF, 0.1f);
    EXPECT_EQ(p.omegaStart, 0.001f);
    EXPECT_EQ(p.omegaMax, 0.1f);
    EXPECT_EQ(p.omegaStep, 0.001f);
    EXPECT_EQ(cfg.grouping.proxy, GroupingProxy::Box);
    EXPECT_FALSE(cfg.grouping.forest.has_value());
}

TEST(GroupingConfig, readsEveryKey) {
    TempDir dir;
    const StationConfig cfg = loadStationConfig(dir.write("a.yaml", std::string(kGroupingScene) + R"(grouping:
  l0: 100
  alpha_p: 1
  alpha_s: 2
  alpha_c: 3
  alpha_f: 4
  omega_t: 0.02
  omega_t_start: 0.01
  omega_t_max: 0.2
  omega_t_step: 0.01
  proxy: impostor
  proxy_alpha: 0.5
  impostor_pixels_per_unit: 2
  objects: true
  forest: green
)"));
    const GroupingConfig& g = cfg.grouping;
    EXPECT_EQ(g.params.l0, 100.0f);
    EXPECT_EQ(g.params.alphaF, 4.0f);
    EXPECT_EQ(g.params.omegaT, 0.02f);
    EXPECT_EQ(g.params.stepCount(), 20);
    EXPECT_EQ(g.proxy, GroupingProxy::Impostor);
    EXPECT_EQ(g.proxyAlpha, 0.5f);
    EXPECT_TRUE(g.objects);
    ASSERT_TRUE(g.forest.has_value());
    EXPECT_EQ(*g.forest, ForestColouring::Green);
}

TEST(GroupingConfig, badValuesAreReportedWithTheirLine) {
    TempDir dir;
    const auto file = dir.write("a.yaml", std::string(kGroupingScene) + R"(grouping:
  alpha_p: -1
  proxy: sphere
  forset: mixed
)");
    try {
        loadStationConfig(file);
        FAIL() << "expected a ConfigError";
    } catch (const ConfigError& e) {
        ASSERT_EQ(e.issues.size(), 3u);
        EXPECT_EQ(e.issues[0].line, 6);
        EXPECT_EQ(e.issues[1].line, 7);
        EXPECT_EQ(e.issues[2].line, 8);
    }
}

TEST(GroupingConfig, forestConfigBuildsTheGroupedForest) {
    SceneFile f = loadSceneFile(std::filesystem::path(ARCOMP_SOURCE_DIR) / "configs/forest-grouping.yaml");
    ASSERT_EQ(f.world.grouping.nodes.size(), 1u);
    const GroupingNode& g = f.world.grouping.nodes[0];
    EXPECT_EQ(g.objects.size(), kForestTrees);
    EXPECT_EQ(g.omegaT, 0.011f);
    ASSERT_TRUE(f.camera.has_value());
    f.world.scene.update();
    DrawList grouped, full;
    select(f.world, *f.camera, {}, grouped);
    select(f.world, *f.camera, {.lod = false, .grouping = false}, full);
    const std::size_t groundTriangles = 12;
    EXPECT_EQ(drawnTriangles(f.world.scene, full), kForestTrees * kTreeTriangles + groundTriangles);
    EXPECT_LT(drawnTriangles(f.world.scene, grouped), drawnTriangles(f.world.scene, full) / 4);
}

TEST(GroupingConfig, objectsTrueGroupsTheConfigsObjects) {
    TempDir dir;
    SceneFile f = loadSceneFile(dir.write("a.yaml", R"(scene:
  objects:
    - shape: box
      size: [100, 100, 100]
      position: [0, 0, 0]
    - shape: box
      size: [100, 100, 100]
      position: [100, 0, 0]
grouping:
  objects: true
)"));
    ASSERT_EQ(f.world.grouping.nodes.size(), 1u);
    const GroupingTree& tree = f.world.grouping.nodes[0].tree;
    EXPECT_EQ(tree.objectCount(), 2u);
    ASSERT_EQ(tree.roots().size(), 1u) << "two touching boxes of one colour group";
    EXPECT_FALSE(tree.isLeaf(tree.roots()[0]));
}
