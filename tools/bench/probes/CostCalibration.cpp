#include "tools/bench/probes/CostCalibration.hpp"
#include "graph/budget/OnScreenPixels.hpp"

#include "graph/budget/CostTableFit.hpp"
#include "graph/budget/RecursiveLeastSquares.hpp"
#include "graph/core/View.hpp"
#include "graph/lod/LodAlternatives.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>

namespace arcomp {

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

double timeFrame(const Scene& scene, const DrawList& list, const View& view, Renderer& renderer, FrameTimer& timer,
                 const CalibrationOptions& o) {
    std::vector<double> ms;
    for (int r = 0; r < std::max(o.repeats, 1); ++r) {
        timer.begin();
        renderer.draw(scene, list, view, {.clearColor = o.clearColor});
        ms.push_back(timer.end());
    }
    return median(std::move(ms));
}

// Each calibration frame draws its items in a mix of its own: with every
// item's setting drawn from the same uniform odds, each shading's share of
// the pixels came out near a quarter in every frame, the four A's could not
// be told apart (the fit put Gouraud below unlit), and the table
// over-predicted what a change of settings costs: in bench budget, frames
// the controller raised by over 5% came in 13% under their prediction on
// average. A Dirichlet(1/2) draw gives mixes from nearly pure to even.
std::discrete_distribution<int> randomMix(std::size_t kinds, std::mt19937& rng) {
    std::gamma_distribution<double> share(0.5, 1.0);
    std::vector<double> weights(kinds);
    for (double& w : weights) w = share(rng) + 1e-9;  // never all zero
    return std::discrete_distribution<int>(weights.begin(), weights.end());
}

}  // namespace

CostModel calibrateCosts(const Scene& scene, std::span<const NodeId> levelMeshes, Renderer& renderer, FrameTimer& timer,
                         const CalibrationOptions& o) {
    CostModel model(levelMeshes.size());
    if (levelMeshes.empty()) return model;
    const Sphere bound = scene.worldBound(levelMeshes[0]);
    const float screen = static_cast<float>(o.viewport.x) * static_cast<float>(o.viewport.y);
    const float fovy = 45.0f;
    const float pixelScale = static_cast<float>(o.viewport.y) * 0.5f / std::tan(glm::radians(fovy) * 0.5f);

    // Every level's geometry reaches the GPU, and every shading's program is
    // compiled (llvmpipe compiles on first draw), before anything is timed.
    const View overview = View::framing(bound, fovy, o.viewport);
    for (int s = 0; s < kShadingCount; ++s) {
        DrawList warm;
        for (NodeId n : levelMeshes)
            warm.items.push_back({n, scene.meshPart(n), 1.0f, 1.0f, 0, static_cast<Shading>(s)});
        timer.begin();
        renderer.draw(scene, warm, overview, {.clearColor = o.clearColor});
        timer.end();
    }

    DrawList empty;
    model.overheadMs = timeFrame(scene, empty, overview, renderer, timer, o);

    for (std::size_t level = 0; level < levelMeshes.size(); ++level) {
        const NodeId node = levelMeshes[level];
        for (int s = 0; s < kShadingCount; ++s) {
            const auto shading = static_cast<Shading>(s);
            RecursiveLeastSquares fit(2, 1.0);
            for (float fraction : o.screenFractions) {
                // Distance at which the bounding sphere's disc covers `fraction` of the screen.
                const float radiusPx = std::sqrt(fraction * screen / std::numbers::pi_v<float>);
                const float distance = std::max(bound.radius * pixelScale / radiusPx, bound.radius * 1.01f);
                const glm::vec3 eye = bound.center + o.viewDirection * distance;
                const View view = View::lookAt(eye, bound.center, {0, 1, 0}, fovy, o.viewport,
                                               std::max(1e-3f * distance, distance - 1.5f * bound.radius),
                                               distance + 1.5f * bound.radius);
                DrawList list;
                list.items.push_back({node, scene.meshPart(node), distance, view.projectedArea(bound),
                                      static_cast<std::uint8_t>(level), shading});
                const double ms = timeFrame(scene, list, view, renderer, timer, o) - model.overheadMs;
                fit.add(std::array{static_cast<double>(onScreenPixels(list.items[0], scene, view)), 1.0}, ms);
            }
            // A negative slope or intercept is noise around zero.
            model.set(level, shading, {std::max(0.0, fit.parameters()[0]), std::max(0.0, fit.parameters()[1])});
        }
    }
    model.resetFit();
    return model;
}

CostModel fitCostsOnFrames(const Scene& scene, std::span<const DrawList> lists, std::span<const View> views,
                           Renderer& renderer, FrameTimer& timer, const CostModel& prior, int frames,
                           const CalibrationOptions& o, unsigned seed) {
    if (lists.empty() || lists.size() != views.size() || frames < 1) return prior;
    CostTableFit fit(prior);
    const LodAlternatives alternatives(scene);
    std::mt19937 rng(seed);
    std::uniform_int_distribution<std::size_t> pickList(0, lists.size() - 1);
    DrawList list;
    std::vector<ChargedItem> charged;
    for (int f = 0; f < frames; ++f) {
        const std::size_t i = pickList(rng);
        list = lists[i];
        charged.clear();
        std::discrete_distribution<int> pickLevel = randomMix(prior.levels(), rng);
        std::discrete_distribution<int> pickShading = randomMix(kShadingCount, rng);
        for (DrawItem& item : list.items) {
            const int levelCount = alternatives.levelCount(item.node);
            const auto level = static_cast<std::uint8_t>(std::min(pickLevel(rng), levelCount - 1));
            item.node = alternatives.levelNode(item.node, level);
            item.part = scene.meshPart(item.node);
            item.level = level;
            item.shading = static_cast<Shading>(pickShading(rng));
            charged.push_back({item.level, item.shading, onScreenPixels(item, scene, views[i])});
        }
        const double ms = timeFrame(scene, list, views[i], renderer, timer, {.repeats = 1, .clearColor = o.clearColor});
        fit.addFrame(charged, ms - prior.overheadMs);
    }
    return fit.table();
}

}  // namespace arcomp
