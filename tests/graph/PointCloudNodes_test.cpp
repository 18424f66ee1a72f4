#include "graph/PointCloudNodes.hpp"

#include <gtest/gtest.h>

using namespace arcomp;

TEST(PointCloudNodes, addsAPointCloudNodeBoundingItsPoints) {
    Scene scene;
    PointCloudNodes clouds;
    PointCloud cloud;
    cloud.positions = {{-1, 0, 0}, {1, 0, 0}};
    cloud.colors.assign(2, glm::vec4(1.0f));
    cloud.pointSize = 0.1f;
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
