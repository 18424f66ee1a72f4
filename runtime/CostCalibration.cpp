#include "runtime/CostCalibration.hpp"

#include "graph/RecursiveLeastSquares.hpp"
#include "graph/View.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

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

} // namespace

CostModel calibrateCosts(const Scene& scene, std::span<const NodeId> levelMeshes, Renderer& renderer,
                         FrameTimer& timer, const CalibrationOptions& o) {
    CostModel model(levelMeshes.size());
    if (levelMeshes.empty()) return model;
    const Sphere bound = scene.worldBound(levelMeshes[0]);
    const float screen = static_cast<float>(o.viewport.x) * static_cast<float>(o.viewport.y);
    const float fovy = 45.0f;
    const float pixelScale = static_cast<float>(o.viewport.y) * 0.5f / std::tan(glm::radians(fovy) * 0.5f);

    // Every level's geometry reaches the GPU before anything is timed.
    const View overview = View::framing(bound, fovy, o.viewport);
    DrawList warm;
    for (NodeId n : levelMeshes) warm.items.push_back({n, scene.meshPart(n), 1.0f, 1.0f, 0, Shading::Phong});
    renderer.draw(scene, warm, overview, {.clearColor = o.clearColor});
    timer.begin();
    timer.end();

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
                fit.add(std::array{static_cast<double>(list.items[0].screenArea), 1.0}, ms);
            }
            // A negative slope or intercept is noise around zero.
            model.set(level, shading, {std::max(0.0, fit.parameters()[0]), std::max(0.0, fit.parameters()[1])});
        }
    }
    model.resetFit();
    return model;
}

} // namespace arcomp
