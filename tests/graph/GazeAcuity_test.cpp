#include "graph/lod/GazeAcuity.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace arcomp;

namespace {
const GazeAcuityParams paper{};  // a = 5°, c1 = 6°, c2 = 30°/s
}

TEST(GazeAcuity, k1IsOneInsideFovea) {
    EXPECT_FLOAT_EQ(eccentricityAcuity(0.0f, paper), 1.0f);
    EXPECT_FLOAT_EQ(eccentricityAcuity(5.0f, paper), 1.0f);
}

TEST(GazeAcuity, k1FallsOffExponentiallyBeyondFovea) {
    // θ = 11°: exp(-(11 - 5) / 6) = exp(-1); θ = 35°: exp(-30 / 6) = exp(-5).
    EXPECT_NEAR(eccentricityAcuity(11.0f, paper), 0.3678794f, 1e-6f);
    EXPECT_NEAR(eccentricityAcuity(35.0f, paper), 0.0067379f, 1e-6f);
}

TEST(GazeAcuity, k2FallsLinearlyToZeroAtC2) {
    EXPECT_FLOAT_EQ(motionAcuity(0.0f, paper), 1.0f);
    EXPECT_FLOAT_EQ(motionAcuity(15.0f, paper), 0.5f);
    EXPECT_FLOAT_EQ(motionAcuity(30.0f, paper), 0.0f);
    EXPECT_FLOAT_EQ(motionAcuity(60.0f, paper), 0.0f);
}

TEST(GazeAcuity, productOfBothCoefficients) { EXPECT_NEAR(gazeAcuity(11.0f, 15.0f, paper), 0.5f * 0.3678794f, 1e-6f); }

TEST(GazeAcuity, representativePointIsNearestSpherePointToEye) {
    const glm::vec3 p = representativePoint({0, 0, 10}, {0, 0, 0}, 2.0f);
    EXPECT_FLOAT_EQ(p.z, 2.0f);
    EXPECT_FLOAT_EQ(p.x, 0.0f);
    // Eye inside the sphere: the centre stands in.
    EXPECT_EQ(representativePoint({0, 0, 0.5f}, {0, 0, 0}, 2.0f), glm::vec3(0.0f));
}

TEST(GazeAcuity, staticObjectAndViewerHaveNoAngularSpeed) {
    const glm::mat4 world = glm::translate(glm::mat4(1.0f), {0, 0, -10});
    const TrackedPoint before = trackPoint({0, 0, 0}, world, {0, 0, 0}, 1.0f);
    EXPECT_NEAR(before.world.z, -9.0f, 1e-5f);
    EXPECT_FLOAT_EQ(angularSpeed(before, world, {0, 0, 0}, 0.1f), 0.0f);
}

TEST(GazeAcuity, movingObjectSweepsAtAngleOverTime) {
    // Point at (0,0,-9) moves by 0.9 sideways in 0.1 s: atan(0.1) = 5.7106° → 57.106°/s.
    const glm::mat4 before = glm::translate(glm::mat4(1.0f), {0, 0, -10});
    const glm::mat4 after = glm::translate(glm::mat4(1.0f), {0.9f, 0, -10});
    const TrackedPoint t = trackPoint({0, 0, 0}, before, {0, 0, 0}, 1.0f);
    EXPECT_NEAR(angularSpeed(t, after, {0, 0, 0}, 0.1f), 57.1059f, 1e-3f);
}

TEST(GazeAcuity, rotatingObjectMovesItsRepresentativePoint) {
    // Spinning 90° about its own y axis in 1 s, centre fixed: the point at
    // local (0,0,1) goes to (1,0,0), world (1,0,-10). Against (0,0,-9) seen
    // from the origin: atan2(|p × p'|, p · p') = atan2(9, 90) = 5.7106°.
    const glm::mat4 before = glm::translate(glm::mat4(1.0f), {0, 0, -10});
    const glm::mat4 after = glm::rotate(before, glm::radians(90.0f), {0, 1, 0});
    const TrackedPoint t = trackPoint({0, 0, 0}, before, {0, 0, 0}, 1.0f);
    EXPECT_NEAR(t.local.z, 1.0f, 1e-5f);  // the side facing the eye
    EXPECT_NEAR(angularSpeed(t, after, {0, 0, 0}, 1.0f), 5.7106f, 1e-3f);
}

TEST(GazeAcuity, movingViewerCountsLikeMovingObject) {
    const glm::mat4 world = glm::translate(glm::mat4(1.0f), {0, 0, -10});
    const TrackedPoint t = trackPoint({0, 0, 0}, world, {0, 0, 0}, 1.0f);
    EXPECT_NEAR(angularSpeed(t, world, {0.9f, 0, 0}, 0.1f), 57.1059f, 1e-3f);
}
