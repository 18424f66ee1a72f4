#include "graph/grouping/GroupingMeasure.hpp"

#include <gtest/gtest.h>

namespace arcomp {
namespace {

GroupingItem cube(glm::vec3 c, float edge, glm::vec3 color) {
    return groupingItem(Box{c - glm::vec3(edge * 0.5f), c + glm::vec3(edge * 0.5f)}, color);
}

TEST(GroupingMeasure, touchingEqualCubesOfOneColourCostOnlyTheirDistance) {
    const GroupingParams p;
    const GroupingItem a = cube({0, 0, 0}, 200, {0.1f, 0.5f, 0.1f});
    const GroupingItem b = cube({200, 0, 0}, 200, {0.1f, 0.5f, 0.1f});
    // Ms = 0 (the enclosing box is exactly both), Mc = 0: Ω0 = αp·L2/L0.
    EXPECT_FLOAT_EQ(omega0(a, b, p), 0.1f * 200.0f / 5000.0f);
}

TEST(GroupingMeasure, shapeTermIsEnclosingBoxMinusBothOverEnclosingBox) {
    GroupingParams p;
    p.alphaP = 0;
    p.alphaC = 0;
    const GroupingItem a = cube({0, 0, 0}, 1, {});
    const GroupingItem b = cube({2, 0, 0}, 1, {});
    // V12 = 3, V1 + V2 = 2: Ms = 1/3.
    EXPECT_FLOAT_EQ(omega0(a, b, p), 2000.0f * (1.0f / 3.0f) / 5000.0f);
}

TEST(GroupingMeasure, colourAndMotionTermsAreEuclideanDistances) {
    GroupingParams p;
    p.alphaP = 0;
    p.alphaS = 0;
    GroupingItem a = cube({0, 0, 0}, 1, {0.0f, 0.0f, 0.0f});
    GroupingItem b = cube({1, 0, 0}, 1, {0.3f, 0.4f, 0.0f});
    a.velocity = {0, 0, 0};
    b.velocity = {6, 8, 0};
    EXPECT_FLOAT_EQ(omega0(a, b, p), (2000.0f * 0.5f + 0.1f * 10.0f) / 5000.0f);
}

TEST(GroupingMeasure, omegaScalesWithL0OverEyeDistance) {
    const GroupingParams p;
    EXPECT_FLOAT_EQ(omegaAt(0.01f, 5000.0f, p), 0.01f);
    EXPECT_FLOAT_EQ(omegaAt(0.01f, 10000.0f, p), 0.005f);
}

TEST(GroupingMeasure, redAndGreenNeverGroupWithThePapersConstants) {
    const GroupingParams p;
    const GroupingItem green = cube({0, 0, 0}, 200, {0.1f, 0.5f, 0.1f});
    const GroupingItem red = cube({200, 0, 0}, 200, {0.8f, 0.1f, 0.1f});
    EXPECT_GE(omega0(green, red, p), p.omegaMax);
}

TEST(GroupingMeasure, isSymmetricBitForBit) {
    const GroupingParams p;
    const GroupingItem a = cube({0.3f, 1.7f, -2}, 1.3f, {0.2f, 0.7f, 0.1f});
    const GroupingItem b = cube({5.1f, 0.2f, 3}, 0.7f, {0.25f, 0.6f, 0.3f});
    EXPECT_EQ(omega0(a, b, p), omega0(b, a, p));
}

TEST(GroupingMeasure, paperStepsRunFrom0001To01In100Steps) {
    const GroupingParams p;
    EXPECT_EQ(p.stepCount(), 100);
    EXPECT_NEAR(p.lastThreshold(), 0.1, 1e-6);  // the constants are floats
}

}  // namespace
}  // namespace arcomp
