// The per-object cost model t = A·pixels + B and its online re-fit.
#include "graph/CostModel.hpp"

#include <gtest/gtest.h>

using namespace arcomp;

TEST(CostModel, objectCostIsAPixelsPlusBForItsLevelAndShading) {
    CostModel m(2);
    m.set(0, Shading::Phong, {.msPerPixel = 4e-6, .ms = 2.0});
    m.set(1, Shading::Flat, {.msPerPixel = 1e-6, .ms = 0.5});
    EXPECT_DOUBLE_EQ(m.itemMs(0, Shading::Phong, 1e5), 2.4);
    EXPECT_DOUBLE_EQ(m.itemMs(1, Shading::Flat, 1e5), 0.6);
    EXPECT_DOUBLE_EQ(m.itemMs(0, Shading::Unlit, 1e5), 0.0);
    // A level beyond the table costs what the coarsest does.
    EXPECT_DOUBLE_EQ(m.itemMs(5, Shading::Flat, 1e5), 0.6);
}

TEST(CostModel, frameIsTheSumOverItemsPlusOverhead) {
    CostModel m(1);
    m.set(0, Shading::Phong, {.msPerPixel = 1e-5, .ms = 1.0});
    m.overheadMs = 3.0;
    DrawList list;
    list.items.push_back({0, {0, 0}, 1.0f, 1e5f, 0, Shading::Phong});
    list.items.push_back({1, {0, 0}, 1.0f, 2e5f, 0, Shading::Phong});
    EXPECT_DOUBLE_EQ(m.itemsMs(list), 5.0);
    EXPECT_DOUBLE_EQ(m.frameMs(m.itemsMs(list)), 8.0);
}

TEST(CostModel, refitFollowsAMachineSlowerThanCalibrated) {
    CostModel m(1);
    m.overheadMs = 2.0;
    // The table says items; the machine takes 1.4 times as long, plus 1 ms more overhead.
    for (int i = 0; i < 300; ++i) {
        const double items = 10.0 + (i % 13);
        m.observe(items, 1.4 * items + 3.0);
    }
    EXPECT_NEAR(m.gain(), 1.4, 0.02);
    EXPECT_NEAR(m.frameMs(20.0), 31.0, 0.2);
}

TEST(CostModel, withoutRefitThePredictionIsTheTable) {
    CostModel m(1);
    m.overheadMs = 2.0;
    m.enableRefit(false);
    for (int i = 0; i < 50; ++i) m.observe(10.0, 40.0);
    EXPECT_DOUBLE_EQ(m.frameMs(10.0), 12.0);
}
