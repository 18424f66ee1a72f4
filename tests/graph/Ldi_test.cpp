#include "graph/points/Ldi.hpp"

#include <gtest/gtest.h>

using namespace arcomp;

namespace {

LdiCamera cameraAt(glm::vec3 eye) { return LdiCamera::lookAt(eye, {0, 0, 0}, {0, 1, 0}, 40.0f, 32, 32); }

glm::vec3 onPixelRay(const LdiCamera& c, int x, int y, float depthAlongRay) {
    return c.eye + c.rayDirection(x, y) * depthAlongRay;
}

}  // namespace

TEST(Ldi, lxIsDepthTimesScreenOffsetOverScreenDistance) {
    // Lx = Dx * Lp / D0: 10 units deep, 0.5 px off the centre, screen 100 px away.
    EXPECT_FLOAT_EQ(rayDistanceLx(10.0f, 0.5f, 100.0f), 0.05f);
    EXPECT_FLOAT_EQ(rayDistanceLx(20.0f, 0.5f, 100.0f), 0.1f);  // twice as deep: rays twice as far apart
    EXPECT_FLOAT_EQ(rayDistanceLx(10.0f, 0.0f, 100.0f), 0.0f);
}

TEST(Ldi, placementMeasuresFromTheNearestPixelCentre) {
    const LdiCamera c = cameraAt({0, 0, -10});
    const LdiPlacement centred = placeInLdi(c, onPixelRay(c, 5, 7, 9.0f));
    ASSERT_TRUE(centred.valid);
    EXPECT_EQ(centred.pixel, 7u * 32u + 5u);
    EXPECT_NEAR(centred.lx, 0.0f, 1e-4f);
    // Moved a quarter pixel right at depth z: Lp = 0.25 px, Lx = z * 0.25 / focal.
    const glm::vec3 p = onPixelRay(c, 5, 7, 9.0f);
    const float z = c.toCamera(p).z;
    const glm::vec3 right = glm::transpose(c.rotation)[0];
    const LdiPlacement moved = placeInLdi(c, p + right * (0.25f * z / c.focal));
    EXPECT_EQ(moved.pixel, centred.pixel);
    EXPECT_NEAR(moved.lx, z * 0.25f / c.focal, 1e-4f);
    EXPECT_FALSE(placeInLdi(c, {0, 0, -20}).valid) << "behind the eye";
}

TEST(Ldi, eachPointGoesToTheLdiWithSmallestLx) {
    const std::vector<LdiCamera> cams = {cameraAt({0, 0, -10}), cameraAt({10, 0, 0})};
    PointCloud cloud;
    // On a pixel-centre ray of camera 0, on one of camera 1, and a point
    // whose Lx we compare by hand.
    cloud.positions = {onPixelRay(cams[0], 12, 19, 10.5f), onPixelRay(cams[1], 20, 9, 9.5f), {0.31f, -0.17f, 0.23f}};
    cloud.colors.assign(cloud.positions.size(), glm::vec4(1.0f));
    const LdiPlacement in0 = placeInLdi(cams[0], cloud.positions[2]);
    const LdiPlacement in1 = placeInLdi(cams[1], cloud.positions[2]);
    ASSERT_NE(in0.lx, in1.lx);
    const LdiSet set = buildLdis(cloud, cams);
    EXPECT_EQ(set.pointLdi[0], 0);
    EXPECT_EQ(set.pointLdi[1], 1);
    EXPECT_EQ(set.pointLdi[2], in0.lx < in1.lx ? 0 : 1);
    EXPECT_EQ(set.ldis[0].size() + set.ldis[1].size(), cloud.size());
    const LdiPlacement chosen = set.pointLdi[2] == 0 ? in0 : in1;
    const Ldi& ldi = set.ldis[set.pointLdi[2]];
    EXPECT_NE(std::find(ldi.points.begin() + ldi.pixelStart[chosen.pixel],
                        ldi.points.begin() + ldi.pixelStart[chosen.pixel + 1], 2u),
              ldi.points.begin() + ldi.pixelStart[chosen.pixel + 1]);
}

TEST(Ldi, pixelListsAreSortedByDepthAlongTheRay) {
    const LdiCamera c = cameraAt({0, 0, -10});
    PointCloud cloud;
    for (float d : {12.0f, 9.0f, 11.0f, 10.0f}) cloud.positions.push_back(onPixelRay(c, 16, 16, d));
    cloud.colors.assign(cloud.positions.size(), glm::vec4(1.0f));
    const LdiSet set = buildLdis(cloud, {c});
    const Ldi& ldi = set.ldis[0];
    const std::uint32_t px = 16u * 32u + 16u;
    ASSERT_EQ(ldi.pixelStart[px + 1] - ldi.pixelStart[px], 4u);
    const std::vector<std::uint32_t> ids(ldi.points.begin() + ldi.pixelStart[px],
                                         ldi.points.begin() + ldi.pixelStart[px + 1]);
    EXPECT_EQ(ids, (std::vector<std::uint32_t>{1, 3, 2, 0}));
    for (std::uint32_t k = ldi.pixelStart[px] + 1; k < ldi.pixelStart[px + 1]; ++k)
        EXPECT_LT(ldi.rayDepth[k - 1], ldi.rayDepth[k]);
}

TEST(Ldi, camerasAroundFrameTheWholeSphere) {
    const Sphere bound{{1, 2, 3}, 2.0f};
    for (int count : {1, 3, 6, 7}) {
        const auto cams = ldiCamerasAround(bound, count, 0.05f);
        ASSERT_EQ(cams.size(), static_cast<std::size_t>(count));
        for (const LdiCamera& c : cams) {
            EXPECT_GT(glm::distance(c.eye, bound.center), bound.radius);
            const glm::vec3 q = c.toCamera(bound.center);
            EXPECT_NEAR(q.x, 0.0f, 1e-4f);
            EXPECT_NEAR(q.y, 0.0f, 1e-4f);
            // One pixel is about 0.05 wide at the centre.
            EXPECT_NEAR(q.z / c.focal, 0.05f, 0.002f);
        }
    }
}
