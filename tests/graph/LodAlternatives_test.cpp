// Which mesh nodes are the other levels of an LOD node.
#include "graph/lod/LodAlternatives.hpp"

#include <gtest/gtest.h>

using namespace arcomp;

TEST(LodAlternatives, levelsOfAnLodNodeOfMeshesAreFoundFinestFirst) {
    Scene scene;
    const std::uint32_t g = scene.addGeometry(makeBox({1, 1, 1}));
    const std::uint32_t m = scene.addMaterial({});
    const NodeId lod = scene.addNode(scene.root(), NodeKind::Lod, 0);
    const NodeId l0 = scene.addMesh(lod, {g, m});
    const NodeId l1 = scene.addMesh(lod, {g, m});
    const NodeId l2 = scene.addMesh(lod, {g, m});
    const NodeId plain = scene.addMesh(scene.root(), {g, m});
    scene.update();
    const LodAlternatives alts(scene);
    EXPECT_EQ(alts.levelCount(l1), 3);
    EXPECT_EQ(alts.levelNode(l0, 2), l2);
    EXPECT_EQ(alts.levelNode(l2, 0), l0);
    EXPECT_EQ(alts.object(l1), l0);
    EXPECT_EQ(alts.levelNode(l0, 7), l2);  // clamped to the coarsest
    EXPECT_EQ(alts.levelCount(plain), 1);
    EXPECT_EQ(alts.levelNode(plain, 2), plain);
}

TEST(LodAlternatives, lodNodeWithASubtreeLevelHasNoAlternatives) {
    Scene scene;
    const std::uint32_t g = scene.addGeometry(makeBox({1, 1, 1}));
    const std::uint32_t m = scene.addMaterial({});
    const NodeId lod = scene.addNode(scene.root(), NodeKind::Lod, 0);
    const NodeId l0 = scene.addMesh(lod, {g, m});
    const NodeId group = scene.addGroup(lod);
    scene.addMesh(group, {g, m});
    scene.update();
    const LodAlternatives alts(scene);
    EXPECT_EQ(alts.levelCount(l0), 1);
    EXPECT_EQ(alts.levelNode(l0, 1), l0);
}
