// The station config's point_clouds section and the cloud nodes it adds.

#include "runtime/config/ConfigError.hpp"
#include "runtime/config/StationConfig.hpp"
#include "runtime/station/SceneFile.hpp"

#include "../support/TempDir.hpp"

#include <gtest/gtest.h>

#include <algorithm>

using namespace arcomp;
using arcomp::test::TempDir;

namespace {

const char* const kCloudScene = R"(scene:
  objects:
    - shape: box
)";

}  // namespace

TEST(PointCloudConfig, absentSectionAddsNoClouds) {
    TempDir dir;
    EXPECT_TRUE(loadStationConfig(dir.write("a.yaml", kCloudScene)).pointClouds.clouds.empty());
    SceneFile f = loadSceneFile(dir.write("b.yaml", kCloudScene));
    EXPECT_EQ(f.world.pointClouds.size(), 0u);
}

TEST(PointCloudConfig, treeEntryBecomesAPointCloudNodeWithItsLdis) {
    TempDir dir;
    SceneFile f = loadSceneFile(dir.write("a.yaml", std::string(kCloudScene) + R"(point_clouds:
  - name: oak
    seed: 3
    resolution: 40
    ldis: 3
    position: [5, 0, 0]
    scale: 2
)"));
    ASSERT_EQ(f.world.pointClouds.size(), 1u);
    f.world.scene.update();
    NodeId cloud = kNoNode;
    for (NodeId n = 0; n < f.world.scene.nodeCount(); ++n)
        if (f.world.scene.kind(n) == NodeKind::PointCloud) cloud = n;
    ASSERT_NE(cloud, kNoNode);
    EXPECT_EQ(f.world.scene.name(cloud), "oak");
    const LdiSet& set = f.world.pointClouds.at(f.world.scene, cloud);
    EXPECT_EQ(set.ldis.size(), 3u);
    EXPECT_GT(set.cloud.size(), 100u);
    EXPECT_NEAR(f.world.scene.world(cloud)[3].x, 5.0f, 1e-6f);
    EXPECT_NEAR(glm::length(glm::vec3(f.world.scene.world(cloud)[0])), 2.0f, 1e-5f);
}

TEST(PointCloudConfig, badValuesAndUnknownKeysAreReportedWithTheirLine) {
    TempDir dir;
    const auto file = dir.write("a.yaml", std::string(kCloudScene) + R"(point_clouds:
  - ldis: 0
    source: mesh
    colour: red
)");
    try {
        loadStationConfig(file);
        FAIL() << "expected a ConfigError";
    } catch (const ConfigError& e) {
        std::vector<int> lines;
        for (const ConfigIssue& issue : e.issues) lines.push_back(issue.line);
        std::sort(lines.begin(), lines.end());
        EXPECT_EQ(lines, (std::vector<int>{5, 6, 7}));
    }
}

TEST(PointCloudConfig, unreadableVoxelFileIsAWarningNotAFailure) {
    TempDir dir;
    dir.write("broken.arvox", "not a voxel file");
    SceneFile f = loadSceneFile(dir.write("a.yaml", std::string(kCloudScene) + R"(point_clouds:
  - name: broken
    source: voxels
    voxels: broken.arvox
)"));
    EXPECT_EQ(f.world.pointClouds.size(), 0u);
    ASSERT_EQ(f.warnings.size(), 1u);
    EXPECT_NE(f.warnings[0].find("broken"), std::string::npos);
}
