#include "graph/core/SelectPass.hpp"
#include "graph/points/PointCloudNodes.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

using namespace arcomp;

namespace {

PointCloud twoPoints() {
    PointCloud cloud;
    cloud.positions = {{-1, 0, 0}, {1, 0, 0}};
    cloud.colors.assign(2, glm::vec4(1.0f));
    cloud.pointSize = 0.1f;
    return cloud;
}

}  // namespace

TEST(PointCloudNodes, addsAPointCloudNodeBoundingItsPoints) {
    Scene scene;
    PointCloudNodes clouds;
    const PointCloud cloud = twoPoints();
    const auto cams = ldiCamerasAround(Sphere{{0, 0, 0}, 1.0f}, 3, 0.1f);
    const NodeId node = clouds.add(scene, scene.root(), buildLdis(cloud, cams), "tree");
    scene.update();
    EXPECT_EQ(scene.kind(node), NodeKind::PointCloud);
    EXPECT_EQ(scene.name(node), "tree");
    EXPECT_EQ(clouds.at(scene, node).cloud.size(), 2u);
    EXPECT_EQ(clouds.at(scene, node).ldis.size(), 3u);
    EXPECT_GE(scene.worldBound(node).radius, 1.1f - 1e-5f) << "centres plus the footprint";
    EXPECT_THROW(clouds.at(scene, scene.root()), std::out_of_range);
}

TEST(PointCloudNodes, selectBinsTheCloudsInViewWithTheirDistance) {
    World world;
    Scene& scene = world.scene;
    PointCloudNodes& clouds = world.pointClouds;
    const PointCloud cloud = twoPoints();
    const auto cams = ldiCamerasAround(Sphere{{0, 0, 0}, 1.0f}, 1, 0.1f);
    const NodeId ahead = clouds.add(
        scene, scene.addTransform(scene.root(), glm::translate(glm::mat4(1.0f), {0, 0, -10})), buildLdis(cloud, cams));
    clouds.add(scene, scene.addTransform(scene.root(), glm::translate(glm::mat4(1.0f), {0, 0, 10})),
               buildLdis(cloud, cams));
    scene.update();
    DrawList list;
    select(world, View::lookAt({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60.0f, {64, 64}), {}, list);
    ASSERT_EQ(list.pointClouds.size(), 1u) << "the cloud behind the eye is culled";
    EXPECT_EQ(list.pointClouds[0].node, ahead);
    EXPECT_NEAR(list.pointClouds[0].viewDistance, 10.0f, 1e-4f);
    EXPECT_TRUE(list.items.empty());
}
