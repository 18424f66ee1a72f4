#include "graph/core/Scene.hpp"
#include "graph/core/SelectPass.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using namespace arcomp;

namespace {
struct Fixture {
    World world;
    Scene& scene = world.scene;
    std::uint32_t geometry, material;
    Fixture() {
        geometry = scene.addGeometry(makeBox({1, 1, 1}));
        material = scene.addMaterial({});
    }
    NodeId meshAt(NodeId parent, glm::vec3 position) {
        const NodeId t = scene.addTransform(parent, glm::translate(glm::mat4(1), position));
        scene.addMesh(t, {geometry, material});
        return t;
    }
};
}  // namespace

TEST(Scene, worldMatrixComposesParents) {
    Fixture f;
    const NodeId a = f.scene.addTransform(f.scene.root(), glm::translate(glm::mat4(1), {1, 0, 0}));
    const NodeId b = f.scene.addTransform(a, glm::scale(glm::mat4(1), {2, 2, 2}));
    const NodeId c = f.scene.addTransform(b, glm::translate(glm::mat4(1), {0, 1, 0}));
    f.scene.update();
    const glm::vec4 origin = f.scene.world(c) * glm::vec4(0, 0, 0, 1);
    EXPECT_FLOAT_EQ(origin.x, 1.0f);
    EXPECT_FLOAT_EQ(origin.y, 2.0f);
}

TEST(Scene, changingALocalUpdatesDescendantsAndAncestorBounds) {
    Fixture f;
    const NodeId group = f.scene.addGroup(f.scene.root());
    const NodeId moved = f.meshAt(group, {0, 0, 0});
    const NodeId still = f.meshAt(group, {5, 0, 0});
    f.scene.update();
    const glm::mat4 stillWorld = f.scene.world(still);
    f.scene.setLocal(moved, glm::translate(glm::mat4(1), {0, 0, -20}));
    f.scene.update();
    const NodeId mesh = f.scene.children(moved)[0];
    EXPECT_FLOAT_EQ(f.scene.worldBound(mesh).center.z, -20.0f);
    EXPECT_TRUE(contains(f.scene.worldBound(group), f.scene.worldBound(mesh)));
    EXPECT_TRUE(contains(f.scene.bound(), f.scene.worldBound(f.scene.children(still)[0])));
    EXPECT_EQ(f.scene.world(still), stillWorld);
}

TEST(Scene, depthFirstOrderGivesContiguousSubtrees) {
    Fixture f;
    const NodeId a = f.scene.addGroup(f.scene.root());
    const NodeId b = f.scene.addGroup(f.scene.root());
    f.meshAt(a, {});
    f.meshAt(b, {});
    f.meshAt(a, {});  // added last, but belongs under a
    f.scene.update();
    const auto order = f.scene.order();
    const auto end = f.scene.subtreeEnd();
    ASSERT_EQ(order.size(), f.scene.nodeCount());
    EXPECT_EQ(end[0], order.size());
    for (std::uint32_t pos = 0; pos < order.size(); ++pos)
        for (std::uint32_t inner = pos + 1; inner < end[pos]; ++inner) {
            NodeId n = order[inner];
            while (n != kNoNode && n != order[pos]) n = f.scene.parent(n);
            EXPECT_EQ(n, order[pos]) << "node at " << inner << " is not under the node at " << pos;
        }
}

TEST(SelectPass, culledSubtreesAreSkippedAndVisibleMeshesListed) {
    Fixture f;
    const NodeId ahead = f.scene.addGroup(f.scene.root());
    const NodeId behind = f.scene.addGroup(f.scene.root());
    for (int i = 0; i < 3; ++i) f.meshAt(ahead, {static_cast<float>(i) - 1.0f, 0, -10});
    for (int i = 0; i < 3; ++i) f.meshAt(behind, {static_cast<float>(i), 0, 10});
    f.scene.update();
    const View view = View::lookAt({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60, {640, 480});
    DrawList list;
    select(f.world, view, {.shading = Shading::Flat}, list);
    ASSERT_EQ(list.items.size(), 3u);
    for (const DrawItem& item : list.items) {
        EXPECT_LT(f.scene.worldBound(item.node).center.z, 0.0f);
        EXPECT_EQ(item.shading, Shading::Flat);
        EXPECT_NEAR(item.viewDistance, 10.0f, 1.1f);
        EXPECT_GT(item.screenArea, 0.0f);
    }
    EXPECT_EQ(list.nodesCulled, 1u);  // the whole group behind, in one test
}

TEST(View, projectedAreaFallsWithSquaredDistance) {
    const View v = View::lookAt({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60, {1000, 1000});
    const float near = v.projectedArea({{0, 0, -10}, 1});
    const float far = v.projectedArea({{0, 0, -20}, 1});
    EXPECT_NEAR(near / far, 4.0f, 1e-3f);
    EXPECT_EQ(v.projectedArea({{0, 0, 0}, 1}), 1000.0f * 1000.0f);  // eye inside
}
