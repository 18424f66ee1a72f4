// The select pass with LOD nodes: the level is chosen while culling, and
// only the chosen level's subtree is visited.
#include "graph/core/SelectPass.hpp"
#include "graph/lod/Lod.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>

using namespace arcomp;

namespace {

struct LodRow {
    World world;
    Scene& scene = world.scene;
    LodTable& lods = world.lods;
    std::vector<NodeId> lodNodes;
    std::vector<glm::vec3> positions;
};

// Objects at z = -20 from x = -15 to 15, each an LOD node over three
// sphere meshes; `node` gives each its policy and thresholds.
void buildRow(LodRow& row, const LodNode& node) {
    const std::uint32_t material = row.scene.addMaterial({});
    const std::uint32_t geometries[3] = {row.scene.addGeometry(makeUvSphere(1.0f, 24, 12)),
                                         row.scene.addGeometry(makeUvSphere(1.0f, 12, 6)),
                                         row.scene.addGeometry(makeUvSphere(1.0f, 6, 4))};
    for (int k = 0; k <= 10; ++k) {
        const glm::vec3 at{-15.0f + 3.0f * static_cast<float>(k), 0.0f, -20.0f};
        const NodeId t = row.scene.addTransform(row.scene.root(), glm::translate(glm::mat4(1.0f), at));
        const NodeId lod = row.scene.addNode(t, NodeKind::Lod, row.lods.add(node));
        for (std::uint32_t g : geometries) row.scene.addMesh(lod, {g, material});
        row.lodNodes.push_back(lod);
        row.positions.push_back(at);
    }
    row.scene.update();
}

const View camera = View::lookAt({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60.0f, {1280, 720});

std::uint8_t levelFromK1(float k1) { return k1 >= 0.5f ? 0 : (k1 >= 0.1f ? 1 : 2); }

}  // namespace

TEST(LodSelect, levelsFallOffAwayFromGazeAsK1Says) {
    LodNode node;
    node.policy = LodPolicy::GazeAcuity;
    node.setThresholds({0.5f, 0.1f});
    LodRow row;
    buildRow(row, node);
    const glm::vec3 gaze = glm::normalize(row.positions.front());  // at the leftmost object

    DrawList list;
    select(row.world, camera, {.gaze = gaze, .timeSeconds = 0.0}, list);

    ASSERT_EQ(list.items.size(), row.positions.size());  // one level per object, all in view
    std::vector<std::uint8_t> levels;
    for (std::size_t k = 0; k < row.positions.size(); ++k) {
        const DrawItem& item = list.items[k];
        const float k1 = eccentricityAcuity(angleDegrees(gaze, row.positions[k]), GazeAcuityParams{});
        EXPECT_EQ(item.level, levelFromK1(k1)) << "object " << k;
        EXPECT_EQ(row.scene.parent(item.node), row.lodNodes[k]);
        levels.push_back(item.level);
    }
    EXPECT_TRUE(std::is_sorted(levels.begin(), levels.end()));  // coarser to the right
    EXPECT_EQ(levels.front(), 0);
    EXPECT_EQ(levels.back(), 2);
}

TEST(LodSelect, onlyChosenLevelIsVisited) {
    LodNode node;
    node.setThresholds({50.0f, 200.0f});
    LodRow row;
    buildRow(row, node);
    DrawList list;
    select(row.world, camera, {}, list);
    // root + per object: the LOD node (its transform shares its slot), one of three meshes.
    EXPECT_EQ(list.nodesVisited, 1 + 2 * row.positions.size());
    for (const DrawItem& item : list.items) EXPECT_EQ(item.level, 0);
}

TEST(LodSelect, fastMovingObjectDropsToCoarseLevel) {
    LodNode node;
    node.policy = LodPolicy::GazeAcuity;
    node.setThresholds({0.5f, 0.1f});
    node.hysteresis = 0.0f;
    LodRow row;
    buildRow(row, node);
    const glm::vec3 gaze = glm::normalize(row.positions[5]);  // the middle object, at x = 0
    DrawList list;
    select(row.world, camera, {.gaze = gaze, .timeSeconds = 0.0}, list);
    EXPECT_EQ(list.items[5].level, 0);
    // Move the gazed-at object 2 units sideways within 1/60 s: far beyond c2.
    const NodeId transform = row.scene.parent(row.lodNodes[5]);
    row.scene.setLocal(transform, glm::translate(glm::mat4(1.0f), row.positions[5] + glm::vec3(2, 0, 0)));
    row.scene.update();
    select(row.world, camera, {.gaze = gaze, .timeSeconds = 1.0 / 60.0}, list);
    const auto moved = std::find_if(list.items.begin(), list.items.end(),
                                    [&](const DrawItem& i) { return row.scene.parent(i.node) == row.lodNodes[5]; });
    ASSERT_NE(moved, list.items.end());
    EXPECT_EQ(moved->level, 2);
}

TEST(LodSelect, crossFadeListsBothLevelsWithWeightsSummingToOne) {
    LodNode node;
    node.setThresholds({30.0f, 200.0f});
    node.hysteresis = 0.0f;
    node.fadeSeconds = 0.5f;
    LodRow row;
    buildRow(row, node);
    DrawList list;
    select(row.world, camera, {.timeSeconds = 0.0}, list);
    const View back = View::lookAt({0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 60.0f, {1280, 720});
    select(row.world, back, {.timeSeconds = 0.1}, list);
    select(row.world, back, {.timeSeconds = 0.35}, list);
    // Every object went from under 30 away to at least 30: both levels listed at half weight.
    ASSERT_EQ(list.items.size(), 2 * row.positions.size());
    for (std::size_t k = 0; k < list.items.size(); k += 2) {
        EXPECT_EQ(list.items[k].level, 1);
        EXPECT_EQ(list.items[k + 1].level, 0);
        EXPECT_NEAR(list.items[k].fade, 0.5f, 1e-5f);
        EXPECT_NEAR(list.items[k].fade + list.items[k + 1].fade, 1.0f, 1e-6f);
    }
}

TEST(LodSelect, withLodOffTheFinestLevelIsShown) {
    LodNode node;
    node.setThresholds({1.0f, 2.0f});  // by distance: every object, 20 away, is past both
    LodRow row;
    buildRow(row, node);
    DrawList list;
    select(row.world, camera, {.lod = false}, list);
    ASSERT_EQ(list.items.size(), row.positions.size());
    for (const DrawItem& item : list.items) EXPECT_EQ(item.level, 0);
    select(row.world, camera, {}, list);
    ASSERT_EQ(list.items.size(), row.positions.size());
    for (const DrawItem& item : list.items) EXPECT_EQ(item.level, 2);
}

namespace {

// A unit sphere's geometry moved to `center`.
Geometry sphereAt(glm::vec3 center) {
    Geometry g = makeUvSphere(1.0f, 8, 4);
    for (glm::vec3& p : g.positions) p += center;
    g.finalize();
    return g;
}

}  // namespace

TEST(LodSelect, aLevelOutsideTheViewIsCulledThoughItsLodNodeIsNot) {
    World world;
    Scene& scene = world.scene;
    const std::uint32_t material = scene.addMaterial({});
    LodNode node;
    node.setThresholds({1000.0f});  // every distance here: level 0
    const NodeId lod = scene.addNode(scene.root(), NodeKind::Lod, world.lods.add(node));
    // Level 0 lies far to the right, out of view; level 1 straight ahead.
    scene.addMesh(lod, {scene.addGeometry(sphereAt({60, 0, -20})), material});
    scene.addMesh(lod, {scene.addGeometry(sphereAt({0, 0, -20})), material});
    scene.update();
    DrawList list;
    select(world, camera, {}, list);
    EXPECT_TRUE(list.items.empty());
    EXPECT_EQ(list.nodesCulled, 1u);

    // Far enough for level 1: that one is in view.
    node.setThresholds({1.0f});
    World near;
    const std::uint32_t m = near.scene.addMaterial({});
    const NodeId lod1 = near.scene.addNode(near.scene.root(), NodeKind::Lod, near.lods.add(node));
    near.scene.addMesh(lod1, {near.scene.addGeometry(sphereAt({60, 0, -20})), m});
    const NodeId shown = near.scene.addMesh(lod1, {near.scene.addGeometry(sphereAt({0, 0, -20})), m});
    near.scene.update();
    select(near, camera, {}, list);
    ASSERT_EQ(list.items.size(), 1u);
    EXPECT_EQ(list.items[0].node, shown);
    EXPECT_EQ(list.items[0].level, 1);
}

TEST(LodSelect, aLevelThatIsASubtreeDrawsAllOfIt) {
    World world;
    Scene& scene = world.scene;
    const std::uint32_t material = scene.addMaterial({});
    LodNode node;
    node.setThresholds({1000.0f});
    const NodeId lod = scene.addNode(scene.root(), NodeKind::Lod, world.lods.add(node));
    const NodeId fine = scene.addGroup(lod);
    const NodeId left = scene.addMesh(fine, {scene.addGeometry(sphereAt({-2, 0, -20})), material});
    const NodeId right = scene.addMesh(fine, {scene.addGeometry(sphereAt({2, 0, -20})), material});
    scene.addMesh(lod, {scene.addGeometry(sphereAt({0, 0, -20})), material});
    scene.update();
    DrawList list;
    select(world, camera, {}, list);
    ASSERT_EQ(list.items.size(), 2u);
    EXPECT_EQ(list.items[0].node, left);
    EXPECT_EQ(list.items[1].node, right);
    for (const DrawItem& item : list.items) EXPECT_EQ(item.level, 0);
}
