#include "graph/core/ObjectMotion.hpp"

#include <gtest/gtest.h>

using namespace arcomp;

TEST(ObjectMotion, goesOutToItsRangeAndComesBack) {
    const ObjectMotion m{.velocity = {0.5f, 0.0f, 0.0f}, .range = 2.0f};
    EXPECT_FLOAT_EQ(motionOffset(m, 0.0).x, 0.0f);
    EXPECT_FLOAT_EQ(motionOffset(m, 2.0).x, 1.0f);
    EXPECT_FLOAT_EQ(motionOffset(m, 4.0).x, 2.0f);  // the turning point
    EXPECT_FLOAT_EQ(motionOffset(m, 5.0).x, 1.5f);
    EXPECT_FLOAT_EQ(motionVelocity(m, 5.0).x, -0.5f);
    EXPECT_NEAR(motionOffset(m, 8.0).x, 0.0f, 1e-6f);  // back where it started
    EXPECT_FLOAT_EQ(motionVelocity(m, 9.0).x, 0.5f);
}

TEST(ObjectMotion, withoutRangeItMovesOn) {
    const ObjectMotion m{.velocity = {0.0f, 0.0f, -2.0f}};
    EXPECT_FLOAT_EQ(motionOffset(m, 10.0).z, -20.0f);
    EXPECT_FLOAT_EQ(motionVelocity(m, 10.0).z, -2.0f);
}
