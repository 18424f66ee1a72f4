#include "graph/core/SelectPass.hpp"
#include "graph/lod/Lod.hpp"
#include "graph/silhouette/HoldoutMeshes.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using namespace arcomp;

namespace {

// A sphere mesh node 10 units along x with a holdout whose one region is a
// box of eyes between 3 and 4 units in front of it (in its local space).
struct OneHoldout {
    World world;
    Scene& scene = world.scene;
    HoldoutMeshes& holdouts = world.holdouts;
    SilhouetteMesh silhouette;
    NodeId place, mesh;
    OneHoldout() {
        const Geometry sphere = makeUvSphere(1.0f, 16, 8);
        silhouette = bakeSilhouetteMesh(sphere.positions, sphere.indices,
                                        {ViewRegion::fromBox({{-0.5f, -0.5f, 3}, {0.5f, 0.5f, 4}})});
        place = scene.addTransform(scene.root(), glm::translate(glm::mat4(1.0f), {10, 0, 0}));
        mesh = scene.addMesh(place, {scene.addGeometry(sphere), scene.addMaterial({})});
        holdouts.add(scene, mesh, silhouette, scene.addMaterial({}));
        scene.update();
    }
};

View lookingAtX10From(float z) { return View::lookAt({10, 0, z}, {10, 0, 0}, {0, 1, 0}, 60.0f, {64, 64}); }

}  // namespace

TEST(HoldoutMeshes, selectPutsTheCgItemInTheHoldoutBinWithItsDepth) {
    OneHoldout f;
    // A second mesh in view, with no holdout.
    f.scene.addMesh(f.scene.addTransform(f.scene.root(), glm::translate(glm::mat4(1.0f), {11.5f, 0, 0})),
                    f.scene.meshPart(f.mesh));
    f.scene.update();
    DrawList list;
    select(f.world, lookingAtX10From(6.0f), {}, list);
    ASSERT_EQ(list.items.size(), 2u);
    ASSERT_EQ(list.holdouts.size(), 1u);
    const DrawItem& cg = list.items[list.holdouts[0].cgItem];
    EXPECT_EQ(cg.node, f.mesh);
    EXPECT_NEAR(list.holdouts[0].depth, 6.0f, 1e-4f);  // along the view axis to the sphere's centre
    EXPECT_NE(list.items[1 - list.holdouts[0].cgItem].node, f.mesh);
    // A world without holdouts leaves the bin empty: the CG is drawn all the same.
    World plain;
    plain.scene = f.scene;
    select(plain, lookingAtX10From(6.0f), {}, list);
    EXPECT_EQ(list.items.size(), 2u);
    EXPECT_TRUE(list.holdouts.empty());
}

TEST(HoldoutMeshes, itemForDrawsTheRegionsListFromInsideAndTheFullMeshFromOutside) {
    OneHoldout f;
    DrawList list;
    for (const float z : {3.5f, 8.0f}) {
        const View view = lookingAtX10From(z);
        select(f.world, view, {}, list);
        ASSERT_EQ(list.holdouts.size(), 1u);
        const std::optional<DrawItem> cut = f.holdouts.itemFor(f.scene, list.items[list.holdouts[0].cgItem], view);
        ASSERT_TRUE(cut);
        const SilhouetteRange want = z < 4.0f ? f.silhouette.ranges[0] : f.silhouette.full;
        EXPECT_EQ(cut->firstIndex, want.firstIndex) << z;
        EXPECT_EQ(cut->indexCount, want.indexCount) << z;
        EXPECT_EQ(cut->node, f.mesh);  // the CG node's own world matrix places it
        EXPECT_EQ(cut->shading, Shading::Unlit);
        EXPECT_NE(cut->part.geometry, f.scene.meshPart(f.mesh).geometry);
    }
    EXPECT_LT(f.silhouette.ranges[0].indexCount, f.silhouette.full.indexCount);
}

TEST(HoldoutMeshes, eachLodLevelHasItsOwnHoldoutAndTheChosenOneIsBinned) {
    World world;
    Scene& scene = world.scene;
    LodTable& lods = world.lods;
    LodNode node;
    node.levelCount = 2;
    node.thresholds[0] = 20.0f;  // level 1 beyond 20 units
    const NodeId lod = scene.addNode(scene.root(), NodeKind::Lod, lods.add(node));
    HoldoutMeshes& holdouts = world.holdouts;
    const std::uint32_t material = scene.addMaterial({});
    std::vector<NodeId> levelNodes;
    std::vector<SilhouetteMesh> silhouettes;
    for (const Geometry& level : {makeUvSphere(1.0f, 24, 12), makeUvSphere(1.0f, 6, 4)}) {
        levelNodes.push_back(scene.addMesh(lod, {scene.addGeometry(level), material}));
        silhouettes.push_back(bakeSilhouetteMesh(level.positions, level.indices, {}));
        holdouts.add(scene, levelNodes.back(), silhouettes.back(), material);
    }
    ASSERT_LT(silhouettes[1].full.indexCount, silhouettes[0].full.indexCount);
    scene.update();
    DrawList list;
    for (const auto& [distance, level] : {std::pair{5.0f, 0}, std::pair{40.0f, 1}}) {
        const View view = View::lookAt({0, 0, distance}, {0, 0, 0}, {0, 1, 0}, 60.0f, {64, 64});
        select(world, view, {}, list);
        ASSERT_EQ(list.holdouts.size(), 1u) << distance;
        const DrawItem& cg = list.items[list.holdouts[0].cgItem];
        EXPECT_EQ(cg.node, levelNodes[static_cast<std::size_t>(level)]) << distance;
        // The level's own silhouette, not the finest one's.
        const std::optional<DrawItem> cut = holdouts.itemFor(scene, cg, view);
        ASSERT_TRUE(cut);
        EXPECT_EQ(cut->indexCount, silhouettes[static_cast<std::size_t>(level)].full.indexCount) << distance;
    }
}

// A skinned mesh's holdout is its own geometry, whole, posed by the same
// skin, so the cut-out follows the pose the CG is drawn in.
TEST(HoldoutMeshes, aSkinnedMeshsHoldoutIsItsWholeMeshWithItsSkin) {
    World world;
    Scene& scene = world.scene;
    Geometry g = makeUvSphere(1.0f, 16, 8);
    g.joints.assign(g.positions.size(), {0, 0, 0, 0});
    g.weights.assign(g.positions.size(), {1, 0, 0, 0});
    const NodeId place = scene.addTransform(scene.root(), glm::translate(glm::mat4(1.0f), {10, 0, 0}));
    const NodeId joint[1] = {scene.addTransform(scene.root(), glm::mat4(1.0f))};
    const glm::mat4 bind[1] = {glm::mat4(1.0f)};
    const std::uint32_t skin = scene.addSkin(place, joint, bind);
    const std::uint32_t indexCount = static_cast<std::uint32_t>(g.indices.size());
    const NodeId mesh = scene.addMesh(place, {scene.addGeometry(std::move(g)), scene.addMaterial({}), skin});
    const std::uint32_t holdoutMaterial = scene.addMaterial({});
    world.holdouts.addPosed(scene, mesh, holdoutMaterial);
    scene.update();
    DrawList list;
    const View view = lookingAtX10From(3.5f);
    select(world, view, {}, list);
    ASSERT_EQ(list.holdouts.size(), 1u);
    const std::optional<DrawItem> cut = world.holdouts.itemFor(scene, list.items[list.holdouts[0].cgItem], view);
    ASSERT_TRUE(cut);
    EXPECT_EQ(cut->part.geometry, scene.meshPart(mesh).geometry);
    EXPECT_EQ(cut->part.material, holdoutMaterial);
    EXPECT_EQ(cut->part.skin, skin);
    EXPECT_EQ(cut->firstIndex, 0u);
    EXPECT_EQ(cut->indexCount, indexCount);
}
