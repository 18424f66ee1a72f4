#include "graph/lod/Lod.hpp"

#include <gtest/gtest.h>

using namespace arcomp;

namespace {

LodNode distanceNode(float hysteresis) {
    LodNode n;
    n.policy = LodPolicy::Distance;
    n.setThresholds({50.0f, 200.0f});
    n.hysteresis = hysteresis;
    return n;
}

}  // namespace

TEST(Lod, distanceRangesPickLevelsLikeOsgLod) {
    const LodNode n = distanceNode(0.0f);
    EXPECT_EQ(chooseLevel(n, 0.0f, kNoLevel), 0);
    EXPECT_EQ(chooseLevel(n, 49.9f, kNoLevel), 0);
    EXPECT_EQ(chooseLevel(n, 50.0f, kNoLevel), 1);  // [50, 200) → 1
    EXPECT_EQ(chooseLevel(n, 199.9f, kNoLevel), 1);
    EXPECT_EQ(chooseLevel(n, 200.0f, kNoLevel), 2);
    EXPECT_EQ(chooseLevel(n, 1e6f, kNoLevel), 2);
}

TEST(Lod, acuityThresholdsGiveFineLevelForHighProduct) {
    LodNode n;
    n.policy = LodPolicy::GazeAcuity;
    n.setThresholds({0.5f, 0.1f});
    EXPECT_EQ(chooseLevel(n, lodMetric(n.policy, {.acuity = 1.0f}), kNoLevel), 0);
    EXPECT_EQ(chooseLevel(n, lodMetric(n.policy, {.acuity = 0.5f}), kNoLevel), 0);
    EXPECT_EQ(chooseLevel(n, lodMetric(n.policy, {.acuity = 0.3f}), kNoLevel), 1);
    EXPECT_EQ(chooseLevel(n, lodMetric(n.policy, {.acuity = 0.05f}), kNoLevel), 2);
}

TEST(Lod, screenSizeTimesAcuityWeighsPixelsByAcuity) {
    LodNode n;
    n.policy = LodPolicy::ScreenSizeTimesAcuity;
    n.setThresholds({100.0f, 20.0f});
    // 300 px in the fovea: fine; the same 300 px at k1·k2 = 0.2 is 60 px: middle.
    EXPECT_EQ(chooseLevel(n, lodMetric(n.policy, {.pixels = 300.0f, .acuity = 1.0f}), kNoLevel), 0);
    EXPECT_EQ(chooseLevel(n, lodMetric(n.policy, {.pixels = 300.0f, .acuity = 0.2f}), kNoLevel), 1);
    EXPECT_EQ(chooseLevel(n, lodMetric(n.policy, {.pixels = 50.0f, .acuity = 0.2f}), kNoLevel), 2);
}

TEST(Lod, hysteresisKeepsLevelWithinBand) {
    LodTable table;
    const std::uint32_t i = table.add(distanceNode(0.1f));  // band ±5 around 50
    double t = 0.0;
    const auto at = [&](float d) {
        t += 1.0 / 60.0;
        return table.choose(i, {.distance = d}, t).level;
    };
    EXPECT_EQ(at(40.0f), 0);
    // Hovering across 50 within the band never flips.
    for (int k = 0; k < 10; ++k) {
        EXPECT_EQ(at(49.0f), 0);
        EXPECT_EQ(at(54.0f), 0);
    }
    EXPECT_EQ(at(55.5f), 1);  // past the band: coarser
    for (int k = 0; k < 10; ++k) {
        EXPECT_EQ(at(46.0f), 1);
        EXPECT_EQ(at(51.0f), 1);
    }
    EXPECT_EQ(at(44.0f), 0);  // past the band the other way: finer again
}

TEST(Lod, withoutHysteresisBoundaryFlipsEveryFrame) {
    LodTable table;
    const std::uint32_t i = table.add(distanceNode(0.0f));
    EXPECT_EQ(table.choose(i, {.distance = 49.0f}, 0.0).level, 0);
    EXPECT_EQ(table.choose(i, {.distance = 51.0f}, 0.016).level, 1);
    EXPECT_EQ(table.choose(i, {.distance = 49.0f}, 0.032).level, 0);
}

TEST(Lod, staleNodeChoosesWithoutBand) {
    LodTable table;
    const std::uint32_t i = table.add(distanceNode(0.1f));
    EXPECT_EQ(table.choose(i, {.distance = 40.0f}, 0.0).level, 0);
    // Unseen for a second: its old level no longer holds it.
    EXPECT_EQ(table.choose(i, {.distance = 52.0f}, 1.0).level, 1);
}

TEST(Lod, crossFadeBlendsOldAndNewLevelOverFadeTime) {
    LodNode n = distanceNode(0.0f);
    n.fadeSeconds = 0.2f;
    LodTable table;
    const std::uint32_t i = table.add(n);
    LodChoice c = table.choose(i, {.distance = 40.0f}, 0.0);
    EXPECT_EQ(c.fadingLevel, kNoLevel);
    c = table.choose(i, {.distance = 60.0f}, 0.1);
    EXPECT_EQ(c.level, 1);
    EXPECT_EQ(c.fadingLevel, 0);
    EXPECT_FLOAT_EQ(c.fade, 0.0f);
    c = table.choose(i, {.distance = 60.0f}, 0.2);
    EXPECT_EQ(c.fadingLevel, 0);
    EXPECT_NEAR(c.fade, 0.5f, 1e-6f);
    c = table.choose(i, {.distance = 60.0f}, 0.31);
    EXPECT_EQ(c.fadingLevel, kNoLevel);
    EXPECT_FLOAT_EQ(c.fade, 1.0f);
}

TEST(Lod, nodesWithTheSameRuleKeepTheirOwnHistory) {
    LodTable table;
    const std::uint32_t a = table.add(distanceNode(0.1f)), b = table.add(distanceNode(0.1f));
    EXPECT_EQ(table.choose(a, {.distance = 40.0f}, 0.0).level, 0);
    // 54 is within the band around 50: a, shown fine, stays fine; b, seen
    // for the first time, has no band.
    EXPECT_EQ(table.choose(a, {.distance = 54.0f}, 0.016).level, 0);
    EXPECT_EQ(table.choose(b, {.distance = 54.0f}, 0.016).level, 1);
    EXPECT_EQ(table.previousLevel(a), 0);
    EXPECT_EQ(table.previousLevel(b), 1);
}

TEST(Lod, everyNodeKeepsItsOwnRuleWhereRulesRepeat) {
    // Every third node has the same rule; the others each have their own,
    // so repeats lie both next to each other and far apart.
    const auto nearEdge = [](int k) { return k % 3 == 0 ? 10.0f : 10.0f + static_cast<float>(k); };
    LodTable table;
    std::vector<std::uint32_t> nodes;
    for (int k = 0; k < 40; ++k) {
        LodNode n = distanceNode(0.0f);
        n.setThresholds({nearEdge(k), 1000.0f});
        nodes.push_back(table.add(n));
    }
    for (int k = 0; k < 40; ++k) {
        EXPECT_EQ(table.rule(nodes[k]).thresholds[0], nearEdge(k)) << "node " << k;
        EXPECT_EQ(table.node(nodes[k]).thresholds[0], nearEdge(k)) << "node " << k;
        // Just short of its own first threshold: fine; just past it: coarser.
        EXPECT_EQ(table.choose(nodes[k], {.distance = nearEdge(k) - 0.5f}, 0.0).level, 0) << "node " << k;
        EXPECT_EQ(table.choose(nodes[k], {.distance = nearEdge(k) + 0.5f}, 0.016).level, 1) << "node " << k;
    }
}
