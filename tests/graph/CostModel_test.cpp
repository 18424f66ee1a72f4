// The per-object cost model t = A·pixels + B and its online re-fit.
#include "graph/budget/CostModel.hpp"

#include <gtest/gtest.h>

#include <cmath>

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
    Scene scene;
    const NodeId box = scene.addMesh(scene.root(), {scene.addGeometry(makeBox({1, 1, 1})), scene.addMaterial({})});
    scene.update();
    const View view = View::lookAt({0, 0, 10}, {0, 0, 0}, {0, 1, 0}, 60.0f, {640, 480});
    DrawList list;
    list.items.push_back({box, scene.meshPart(box), 10.0f, 1e5f, 0, Shading::Phong});
    list.items.push_back({box, scene.meshPart(box), 10.0f, 2e5f, 0, Shading::Phong});
    EXPECT_DOUBLE_EQ(m.itemsMs(list, scene, view), 5.0);
    EXPECT_DOUBLE_EQ(m.frameMs(m.itemsMs(list, scene, view)), 8.0);
}

TEST(CostModel, refitFollowsAMachineSlowerThanCalibrated) {
    CostModel m(1);
    m.overheadMs = 2.0;
    // The table says items; the machine takes 1.4 times as long.
    for (int i = 0; i < 100; ++i) {
        const double items = 10.0 + (i % 13);
        m.observe(items, 1.4 * items + 2.0);
    }
    EXPECT_NEAR(m.gain(), 1.4, 0.01);
    EXPECT_NEAR(m.frameMs(20.0), 30.0, 0.2);
}

TEST(CostModel, refitGainConvergesWhileTheControllerHoldsTheFrameTimeSteady) {
    // The case a gain and an offset fitted together cannot resolve: every
    // frame predicts the same sum, 15 ms of items. The machine slows to 1.5
    // times the table; within a few dozen frames the gain says so, and the
    // prediction still scales with what is drawn (a frame of half the
    // items is predicted at half the items' time).
    CostModel m(1);
    m.overheadMs = 2.0;
    for (int i = 0; i < 30; ++i) m.observe(15.0, 15.0 + 2.0);
    EXPECT_NEAR(m.gain(), 1.0, 1e-6);
    int frames = 0;
    while (std::abs(m.gain() - 1.5) > 0.015 && frames < 1000) {
        m.observe(15.0, 1.5 * 15.0 + 2.0);
        ++frames;
    }
    EXPECT_LE(frames, 60);
    EXPECT_NEAR(m.frameMs(7.5), 1.5 * 7.5 + 2.0, 0.2);
}

TEST(CostModel, oneStallMovesTheGainABoundedStepThatFadesALastingChangeComesThrough) {
    CostModel m(1);
    m.overheadMs = 2.0;
    for (int i = 0; i < 50; ++i) m.observe(15.0, 17.0);
    EXPECT_NEAR(m.gain(), 1.0, 1e-9);
    m.observe(15.0, 170.0);  // ten times as long: a stall, not a new machine
    EXPECT_GT(m.gain(), 1.0);
    EXPECT_LE(m.gain(), CostModel::kMaxSampleRatio);  // the sample is clamped, not taken at 11x
    for (int i = 0; i < 8; ++i) m.observe(15.0, 17.0);
    EXPECT_NEAR(m.gain(), 1.0, 0.01);
    // The machine turns 20% slower and stays so: a few frames later the
    // prediction has it.
    for (int i = 0; i < 10; ++i) m.observe(15.0, 1.2 * 15.0 + 2.0);
    EXPECT_NEAR(m.gain(), 1.2, 0.01);
}

TEST(CostModel, theFirstFramesSetTheGainAtOnceAndOnlyThenAreStallsClamped) {
    // A table that under-predicts what is drawn by 2.4 from the first frame
    // (the managed flight's coarse, unlit mix): no steady gain exists yet
    // for the frame to be a stall against.
    CostModel m(1);
    m.overheadMs = 2.0;
    m.observe(15.0, 2.4 * 15.0 + 2.0);
    EXPECT_GT(m.gain(), 1.5);  // clamped, the step would have stopped at 1.25
    for (std::size_t i = 1; i < CostModel::kSettlingFrames; ++i) m.observe(15.0, 2.4 * 15.0 + 2.0);
    EXPECT_NEAR(m.gain(), 2.4, 0.1);
    const double settled = m.gain();
    m.observe(15.0, 170.0);
    EXPECT_LE(m.gain(), settled * CostModel::kMaxSampleRatio);
}

TEST(CostModel, framesThatDrawNothingLeaveTheGainAlone) {
    CostModel m(1);
    m.overheadMs = 2.0;
    for (int i = 0; i < 50; ++i) m.observe(10.0, 1.2 * 10.0 + 2.0);
    const double before = m.gain();
    for (int i = 0; i < 50; ++i) m.observe(0.0, 5.0);
    EXPECT_DOUBLE_EQ(m.gain(), before);
    m.observe(10.0, std::nan(""));
    EXPECT_DOUBLE_EQ(m.gain(), before);
}

TEST(CostModel, withoutRefitThePredictionIsTheTable) {
    CostModel m(1);
    m.overheadMs = 2.0;
    m.enableRefit(false);
    for (int i = 0; i < 50; ++i) m.observe(10.0, 40.0);
    EXPECT_DOUBLE_EQ(m.frameMs(10.0), 12.0);
}
