#include "graph/scenes/ForestExperiment.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace arcomp {
namespace {

std::vector<float> paperThresholds() {
    const GroupingParams p;
    std::vector<float> out;
    for (int k = 0; k < p.stepCount(); ++k) out.push_back(float(p.thresholdAt(k)));
    return out;
}

TEST(ForestExperiment, treesHaveThePapersPolygonCounts) {
    EXPECT_EQ(makeTreeCrown(false).triangleCount() + makeTreeTrunk(false).triangleCount(), kTreeTriangles);
    EXPECT_EQ(makeTreeCrown(true).triangleCount() + makeTreeTrunk(true).triangleCount(), kSimplifiedTreeTriangles);
    ForestExperiment f(ForestColouring::Mixed);
    EXPECT_EQ(f.forest.trees.size(), kForestTrees);
    EXPECT_EQ(f.triangles(ForestMode::Full, 0.05f), 3360u);  // the paper's 32 × 105
}

TEST(ForestExperiment, redTreesNeverGroupWithGreenOnes) {
    ForestExperiment f(ForestColouring::Mixed);
    const GroupingTree& tree = f.world.grouping.nodes[f.world.scene.payload(f.forest.grouping)].tree;
    std::size_t greenGroups = 0;
    for (std::uint32_t n = 0; n < tree.nodeCount(); ++n) {
        if (!tree.alive(n) || tree.isLeaf(n)) continue;
        std::size_t red = 0;
        const auto members = tree.objectsUnder(n);
        for (std::uint32_t o : members) red += f.forest.red[o];
        EXPECT_TRUE(red == 0 || red == members.size()) << "group " << n << " mixes red and green";
        greenGroups += red == 0;
    }
    EXPECT_GT(greenGroups, 0u) << "green trees group with each other";
    // And at every Ωt, each drawn proxy stands for one colour only: the
    // structure above guarantees it; check the drawn cut sees green proxies.
    std::size_t thresholdsWithGreenProxies = 0;
    for (float t : paperThresholds()) {
        const DrawList& list = f.select(ForestMode::Grouped, t);
        for (const DrawItem& item : list.items)
            if (item.model && item.tint.g > item.tint.r) {
                ++thresholdsWithGreenProxies;
                break;
            }
    }
    EXPECT_GT(thresholdsWithGreenProxies, 50u);
}

TEST(ForestExperiment, allGreenForestDrawsNoMoreThanTheMixedOneAtEveryThreshold) {
    ForestExperiment mixed(ForestColouring::Mixed), green(ForestColouring::Green);
    bool fewerSomewhere = false;
    for (float t : paperThresholds()) {
        const std::size_t m = mixed.triangles(ForestMode::Grouped, t), g = green.triangles(ForestMode::Grouped, t);
        EXPECT_LE(g, m) << "Ωt = " << t;
        fewerSomewhere = fewerSomewhere || g < m;
    }
    EXPECT_TRUE(fewerSomewhere);
}

TEST(ForestExperiment, groupingBeatsSimplificationAloneFromSomeThresholdAtMost002) {
    for (ForestColouring c : {ForestColouring::Mixed, ForestColouring::Green}) {
        ForestExperiment f(c);
        float firstBetter = -1.0f;
        for (float t : paperThresholds()) {
            const std::size_t grouped = f.triangles(ForestMode::Grouped, t);
            const std::size_t simplified = f.triangles(ForestMode::Simplified, t);
            EXPECT_LE(grouped, simplified) << "Ωt = " << t;
            if (grouped < simplified && firstBetter < 0.0f) firstBetter = t;
            if (firstBetter >= 0.0f) {
                EXPECT_LT(grouped, simplified) << "from Ωt = " << firstBetter << " on, at " << t;
            }
        }
        EXPECT_GE(firstBetter, 0.0f);
        EXPECT_LE(firstBetter, 0.02f + 1e-6f);
    }
}

TEST(ForestExperiment, simplificationAloneDrawsFewerThanFullDetail) {
    ForestExperiment f(ForestColouring::Green);
    EXPECT_LT(f.triangles(ForestMode::Simplified, 0.01f), f.triangles(ForestMode::Full, 0.01f));
}

}  // namespace
}  // namespace arcomp

namespace arcomp {
namespace {

std::uint32_t topOf(const GroupingTree& t, std::uint32_t n) {
    while (t.parent(n) != kNoGroupingNode) n = t.parent(n);
    return n;
}

TEST(ForestExperiment, aTreeCarriedAwayLeavesItsGroupAndIsDrawnOnItsOwn) {
    ForestExperiment f(ForestColouring::Green);
    const GroupingTree& tree = f.world.grouping.nodes[f.world.scene.payload(f.forest.grouping)].tree;
    ASSERT_EQ(tree.roots().size(), 1u);
    const std::size_t before = f.triangles(ForestMode::Grouped, 0.1f);
    EXPECT_EQ(before, 12u) << "one box";
    // Tree 0 is carried 10 m towards the viewer at 2 m/s.
    f.world.scene.setLocal(f.forest.trees[0],
                           glm::translate(f.world.scene.local(f.forest.trees[0]), {0.0f, 0.0f, 1000.0f}));
    f.world.scene.update();
    const MovedObject moved[] = {{0, {0.0f, 0.0f, 200.0f}}};
    const GroupingRebuildStats s = regroupMoved(f.world.scene, f.forest.grouping, f.world.grouping, moved);
    EXPECT_GT(s.dissolved, 0u);
    EXPECT_EQ(tree.parent(0), kNoGroupingNode);
    EXPECT_EQ(tree.objectsUnder(topOf(tree, 1)).size(), kForestTrees - 1) << "the others stay one group";
    const std::size_t after = f.triangles(ForestMode::Grouped, 0.1f);
    EXPECT_EQ(after, 12u + kTreeTriangles) << "the box of 31 trees and the lone tree, near enough for full detail";
}

TEST(ForestExperiment, treesCarriedTogetherStayGrouped) {
    ForestExperiment f(ForestColouring::Green);
    const GroupingTree& tree = f.world.grouping.nodes[f.world.scene.payload(f.forest.grouping)].tree;
    const std::uint32_t root = tree.roots()[0];
    std::vector<MovedObject> moved;
    for (std::uint32_t i = 0; i < kForestTrees; ++i) {
        f.world.scene.setLocal(f.forest.trees[i],
                               glm::translate(f.world.scene.local(f.forest.trees[i]), {50.0f, 0.0f, 0.0f}));
        moved.push_back({i, {150.0f, 0.0f, 0.0f}});
    }
    f.world.scene.update();
    const GroupingRebuildStats s = regroupMoved(f.world.scene, f.forest.grouping, f.world.grouping, moved);
    EXPECT_EQ(s.dissolved, 0u) << "common motion: Ff = 0";
    ASSERT_EQ(tree.roots().size(), 1u);
    EXPECT_EQ(tree.roots()[0], root);
}

}  // namespace
}  // namespace arcomp

namespace arcomp {
namespace {

TEST(ForestExperiment, anImpostorIsUsedOnlyWhileItsGroupStaysWhereItWasBaked) {
    ForestExperiment f(ForestColouring::Green);
    GroupingNode& g = f.world.grouping.nodes[f.world.scene.payload(f.forest.grouping)];
    const std::uint32_t root = g.tree.roots()[0];
    // As a baker would leave it: a material and the sphere it was made around.
    g.impostorMaterial.assign(g.tree.nodeCount(), GroupingNode::kNoImpostor);
    g.impostorBound.assign(g.tree.nodeCount(), Sphere{});
    g.impostorMaterial[root] = 0;
    g.impostorBound[root] = g.tree.bound(root);
    const auto proxyGeometry = [&] {
        const DrawList& list = f.select(ForestMode::Grouped, 0.1f, GroupingProxy::Impostor);
        EXPECT_EQ(list.items.size(), 1u);
        return list.items.empty() ? ~0u : list.items[0].part.geometry;
    };
    EXPECT_EQ(proxyGeometry(), g.quadGeometry);
    std::vector<MovedObject> moved;
    for (std::uint32_t i = 0; i < kForestTrees; ++i) {
        f.world.scene.setLocal(f.forest.trees[i],
                               glm::translate(f.world.scene.local(f.forest.trees[i]), {400.0f, 0.0f, 0.0f}));
        moved.push_back({i, {100.0f, 0.0f, 0.0f}});
    }
    f.world.scene.update();
    regroupMoved(f.world.scene, f.forest.grouping, f.world.grouping, moved);
    EXPECT_EQ(proxyGeometry(), g.boxPart.geometry) << "moved since baking: the box stands in";
}

}  // namespace
}  // namespace arcomp
