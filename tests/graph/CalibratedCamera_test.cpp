#include "graph/camera/CalibratedCamera.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace arcomp {
namespace {

// A camera 3 m above the floor at z = 10, looking towards -z and 20 degrees
// down, with an off-centre principal point (as real lenses have).
CalibratedCamera kioskCamera() {
    CalibratedCamera c;
    c.intrinsics = {.imageSize = {768, 576}, .fx = 700.0, .fy = 690.0, .cx = 371.5, .cy = 301.25, .distortion = {}};
    // Camera axes in the floor frame: x right, y down, z forward.
    const double tilt = glm::radians(20.0);
    const glm::dvec3 forward(0.0, -std::sin(tilt), -std::cos(tilt));
    const glm::dvec3 right(1.0, 0.0, 0.0);  // looking along -z with +y up, +x is to the right
    const glm::dvec3 down = glm::cross(forward, right);
    c.rotation = glm::transpose(glm::dmat3(right, down, forward));
    c.translation = -c.rotation * glm::dvec3(0.0, 3.0, 10.0);
    return c;
}

glm::dvec2 pixelThroughView(const View& v, const glm::dvec3& p) {
    const glm::dvec4 clip = glm::dmat4(v.viewProjection()) * glm::dvec4(p, 1.0);
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    // NDC to pixel coordinates with pixel centres at integers, v down.
    return {(ndc.x + 1.0) / 2.0 * v.viewport.x - 0.5, (1.0 - ndc.y) / 2.0 * v.viewport.y - 0.5};
}

}  // namespace

TEST(CalibratedCamera, poseGivesPositionHeightAndTilt) {
    const CalibratedCamera c = kioskCamera();
    EXPECT_NEAR(c.position().x, 0.0, 1e-9);
    EXPECT_NEAR(c.heightMetres(), 3.0, 1e-9);
    EXPECT_NEAR(c.position().z, 10.0, 1e-9);
    EXPECT_NEAR(c.tiltDegrees(), 20.0, 1e-9);
}

TEST(CalibratedCamera, theCgViewPutsEveryPointOnThePixelThePinholeModelDoes) {
    const CalibratedCamera c = kioskCamera();
    const View v = c.view(c.intrinsics.imageSize, 0.1f, 100.0f);
    EXPECT_NEAR(v.eye.y, 3.0f, 1e-5f);
    for (const glm::dvec3 p :
         {glm::dvec3(0, 0, 0), glm::dvec3(2.5, 0, 1), glm::dvec3(-3, 1.7, -4), glm::dvec3(1, 0.2, 6)}) {
        const glm::dvec2 expected = c.project(p);
        const glm::dvec2 drawn = pixelThroughView(v, p);
        EXPECT_NEAR(drawn.x, expected.x, 2e-3) << p.x << "," << p.y << "," << p.z;
        EXPECT_NEAR(drawn.y, expected.y, 2e-3) << p.x << "," << p.y << "," << p.z;
    }
    // The floor point straight ahead on the optical axis lands on the principal point.
    const glm::dvec3 onAxis = c.position() + (3.0 / std::sin(glm::radians(20.0))) * glm::dvec3(v.forward);
    EXPECT_NEAR(onAxis.y, 0.0, 1e-6);
    EXPECT_NEAR(pixelThroughView(v, onAxis).x, 371.5, 2e-3);
    EXPECT_NEAR(pixelThroughView(v, onAxis).y, 301.25, 2e-3);
}

TEST(CalibratedCamera, aScaledVideoKeepsEveryPointOnTheSamePartOfTheImage) {
    const CalibratedCamera c = kioskCamera();
    const View half = c.view({384, 288}, 0.1f, 100.0f);
    for (const glm::dvec3 p : {glm::dvec3(2.5, 0, 1), glm::dvec3(-3, 1.7, -4)}) {
        const glm::dvec2 full = c.project(p), scaled = pixelThroughView(half, p);
        // Pixel centres: (u + ½) scales, not u.
        EXPECT_NEAR(scaled.x, (full.x + 0.5) / 2.0 - 0.5, 2e-3);
        EXPECT_NEAR(scaled.y, (full.y + 0.5) / 2.0 - 0.5, 2e-3);
    }
    EXPECT_NEAR(half.fovyRadians, 2.0 * std::atan(288.0 / 2.0 / 345.0), 1e-6);
}

TEST(CalibratedCamera, pointsBehindTheLensHaveNoPixel) {
    const CalibratedCamera c = kioskCamera();
    EXPECT_TRUE(std::isnan(c.project({0.0, 3.0, 20.0}).x));
}

TEST(CalibratedCamera, distortionIsNoticed) {
    CameraIntrinsics k;
    EXPECT_FALSE(k.distorted());
    k.distortion[2] = 1e-4;
    EXPECT_TRUE(k.distorted());
}

TEST(CalibratedCamera, aFootPixelGivesBackTheFloorPointAndItsDepth) {
    const CalibratedCamera c = kioskCamera();
    for (const glm::dvec3 floor : {glm::dvec3(0, 0, 0), glm::dvec3(2.5, 0, 1), glm::dvec3(-3, 0, -4)}) {
        const std::optional<glm::dvec3> found = c.floorPointAt(c.project(floor));
        ASSERT_TRUE(found);
        EXPECT_NEAR(glm::distance(*found, floor), 0.0, 1e-9);
        // Depth is along the optical axis, not the straight-line distance.
        EXPECT_NEAR(c.depthOf(floor), (c.rotation * floor + c.translation).z, 1e-12);
        EXPECT_LT(c.depthOf(floor), glm::distance(c.position(), floor));
    }
    // The top row looks above the horizon (the camera is tilted 20 degrees
    // down with a vertical half-angle of about 23): no floor there.
    EXPECT_FALSE(c.floorPointAt({384.0, 0.0}));
}

}  // namespace arcomp
