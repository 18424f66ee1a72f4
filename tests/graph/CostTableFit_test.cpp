// The cost table corrected by whole frames: the single-object table's A's
// scaled by a gain per shading, its B's by one gain.
#include "graph/budget/CostTableFit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace arcomp;

namespace {

// A table of the shape llvmpipe's has, as one object measured alone gives
// it: a pixel costs more at the fine level and with Phong, an item's fixed
// cost depends on both.
CostModel singleObjectTable() {
    CostModel m(3);
    const double perPixel[3][kShadingCount] = {
        {8e-6, 9e-6, 10e-6, 37e-6}, {4e-6, 5e-6, 5e-6, 23e-6}, {3e-6, 3.5e-6, 4e-6, 19e-6}};
    const double fixed[3][kShadingCount] = {{1.1, 1.2, 1.25, 2.4}, {0.2, 0.2, 0.22, 0.55}, {0.05, 0.06, 0.06, 0.13}};
    for (std::size_t l = 0; l < 3; ++l)
        for (int s = 0; s < kShadingCount; ++s) m.set(l, static_cast<Shading>(s), {perPixel[l][s], fixed[l][s]});
    m.overheadMs = 0.8;
    return m;
}

// What the scene costs: of a disc's pixels, fewer are shaded the dearer the
// shading (hidden ones are cut short by the depth test), and every item's
// fixed cost is a tenth higher.
constexpr double kSceneShare[kShadingCount] = {0.8, 0.9, 0.7, 0.45};
constexpr double kSceneFixed = 1.1;
CostModel sceneTable(const CostModel& single) {
    CostModel m(single.levels());
    for (std::size_t l = 0; l < single.levels(); ++l)
        for (int s = 0; s < kShadingCount; ++s) {
            const CostCoefficients c = single.at(l, static_cast<Shading>(s));
            m.set(l, static_cast<Shading>(s), {kSceneShare[s] * c.msPerPixel, kSceneFixed * c.ms});
        }
    return m;
}

// A frame of 50 items with a mix of its own: half the items at one level,
// the rest anywhere; `allowed` says which pairs may appear.
std::vector<ChargedItem> randomFrame(std::mt19937& rng, bool (*allowed)(std::size_t, Shading)) {
    std::uniform_real_distribution<double> pixels(1e3, 6e4);
    std::uniform_int_distribution<int> level(0, 2), shading(0, kShadingCount - 1);
    const int favourite = level(rng);
    std::vector<ChargedItem> items;
    while (items.size() < 50) {
        const ChargedItem item{static_cast<std::size_t>(rng() % 2 ? favourite : level(rng)),
                               static_cast<Shading>(shading(rng)), pixels(rng)};
        if (allowed(item.level, item.shading)) items.push_back(item);
    }
    return items;
}

double frameMs(const CostModel& m, const std::vector<ChargedItem>& items) {
    double ms = 0.0;
    for (const ChargedItem& item : items) ms += m.itemMs(item.level, item.shading, item.pixels);
    return ms;
}

void addFrames(CostTableFit& fit, const CostModel& t, int frames, bool (*allowed)(std::size_t, Shading),
               unsigned seed) {
    std::mt19937 rng(seed);
    for (int f = 0; f < frames; ++f) {
        const std::vector<ChargedItem> items = randomFrame(rng, allowed);
        fit.addFrame(items, frameMs(t, items));
    }
}

bool anyPair(std::size_t, Shading) { return true; }
bool notLevel1Phong(std::size_t level, Shading s) { return !(level == 1 && s == Shading::Phong); }
bool notFlat(std::size_t, Shading s) { return s != Shading::Flat; }

}  // namespace

TEST(CostTableFit, wholeFramesPredictTheScenesFramesWhereTheSingleObjectTableCannot) {
    const CostModel prior = singleObjectTable();
    const CostModel t = sceneTable(prior);
    CostTableFit fit(prior);
    addFrames(fit, t, 150, anyPair, 1);
    EXPECT_EQ(fit.frames(), 150u);
    const CostModel fitted = fit.table();
    ASSERT_EQ(fitted.levels(), 3u);
    EXPECT_EQ(fitted.overheadMs, prior.overheadMs);
    for (int s = 0; s < kShadingCount; ++s)
        EXPECT_NEAR(fit.gains()[static_cast<std::size_t>(s)], kSceneShare[s], 0.02) << "shading " << s;
    EXPECT_NEAR(fit.gains()[kShadingCount], kSceneFixed, 0.02);
    // Frames it was not fitted on: other random mixes, and the mix the
    // controller makes (near objects fine and lit, far ones coarse and
    // unlit) at both ends of its range.
    std::mt19937 rng(7);
    std::vector<std::vector<ChargedItem>> frames;
    for (int f = 0; f < 40; ++f) frames.push_back(randomFrame(rng, anyPair));
    for (int near : {2, 12}) {
        std::vector<ChargedItem> managed;
        for (int i = 0; i < 50; ++i)
            managed.push_back(i < near ? ChargedItem{0, Shading::Phong, 6e4} : ChargedItem{2, Shading::Unlit, 2e4});
        frames.push_back(managed);
    }
    double fittedError = 0.0, priorError = 0.0;
    for (std::size_t f = 0; f < frames.size(); ++f) {
        SCOPED_TRACE(testing::Message() << "frame " << f);
        const double measured = frameMs(t, frames[f]);
        EXPECT_NEAR(frameMs(fitted, frames[f]), measured, 0.01 * measured);
        fittedError += std::abs(frameMs(fitted, frames[f]) - measured);
        priorError += std::abs(frameMs(prior, frames[f]) - measured);
    }
    EXPECT_LT(fittedError, 0.05 * priorError);
}

TEST(CostTableFit, aPairTheFramesNeverDrawTakesItsShadingsGain) {
    const CostModel prior = singleObjectTable();
    CostTableFit fit(prior);
    addFrames(fit, sceneTable(prior), 150, notLevel1Phong, 2);
    const CostModel fitted = fit.table();
    const double phong = fitted.at(0, Shading::Phong).msPerPixel / prior.at(0, Shading::Phong).msPerPixel;
    EXPECT_NEAR(phong, kSceneShare[static_cast<int>(Shading::Phong)], 0.02);
    EXPECT_DOUBLE_EQ(fitted.at(1, Shading::Phong).msPerPixel, phong * prior.at(1, Shading::Phong).msPerPixel);
}

TEST(CostTableFit, aShadingTheFramesNeverDrawKeepsItsSingleObjectCost) {
    const CostModel prior = singleObjectTable();
    CostTableFit fit(prior);
    addFrames(fit, sceneTable(prior), 150, notFlat, 3);
    const CostModel fitted = fit.table();
    for (std::size_t l = 0; l < 3; ++l)
        EXPECT_DOUBLE_EQ(fitted.at(l, Shading::Flat).msPerPixel, prior.at(l, Shading::Flat).msPerPixel);
    EXPECT_NE(fitted.at(0, Shading::Gouraud).msPerPixel, prior.at(0, Shading::Gouraud).msPerPixel);
}

TEST(CostTableFit, levelsBeyondTheTableAreChargedAsItsLast) {
    CostModel prior(2);
    prior.set(1, Shading::Unlit, {1e-6, 0.1});
    CostTableFit beyond(prior), last(prior);
    const std::vector<ChargedItem> far{{7, Shading::Unlit, 2e4}, {1, Shading::Unlit, 3e4}};
    const std::vector<ChargedItem> asLast{{1, Shading::Unlit, 2e4}, {1, Shading::Unlit, 3e4}};
    for (int f = 0; f < 5; ++f) {
        beyond.addFrame(far, 0.5);
        last.addFrame(asLast, 0.5);
    }
    EXPECT_DOUBLE_EQ(beyond.table().at(1, Shading::Unlit).ms, last.table().at(1, Shading::Unlit).ms);
    EXPECT_NE(beyond.table().at(1, Shading::Unlit).ms, 0.1);
}

TEST(CostTableFit, noCostComesOutBelowZero) {
    CostModel prior(1);
    prior.set(0, Shading::Flat, {1e-5, 0.5});
    CostTableFit fit(prior);
    // Frames that took less than nothing for their items (a mismeasured
    // overhead): the least-squares answer is negative; a cost is not.
    const std::vector<ChargedItem> items{{0, Shading::Flat, 1e3}, {0, Shading::Flat, 1e3}};
    for (int f = 0; f < 20; ++f) fit.addFrame(items, -1.0);
    EXPECT_EQ(fit.table().at(0, Shading::Flat).ms, 0.0);
    EXPECT_GE(fit.table().at(0, Shading::Flat).msPerPixel, 0.0);
}

TEST(CostTableFit, aFrameThatIsNotANumberIsLeftOut) {
    const CostModel prior = singleObjectTable();
    CostTableFit fit(prior);
    const std::vector<ChargedItem> items{{0, Shading::Phong, 3e4}, {2, Shading::Unlit, 1e4}};
    const std::vector<ChargedItem> endless{{0, Shading::Phong, std::numeric_limits<double>::infinity()}};
    fit.addFrame(items, std::numeric_limits<double>::quiet_NaN());
    fit.addFrame(items, std::numeric_limits<double>::infinity());
    fit.addFrame(endless, 5.0);
    EXPECT_EQ(fit.frames(), 0u);
    fit.addFrame(items, 2.0);
    EXPECT_EQ(fit.frames(), 1u);
    for (double g : fit.gains()) EXPECT_TRUE(std::isfinite(g));
    EXPECT_TRUE(std::isfinite(fit.table().itemMs(0, Shading::Phong, 3e4)));
}
