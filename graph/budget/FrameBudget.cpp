#include "graph/budget/FrameBudget.hpp"
#include "graph/budget/OnScreenPixels.hpp"

#include <algorithm>
#include <numeric>

namespace arcomp {

FrameBudget::FrameBudget(CostModel model, BudgetSettings settings) : model_(std::move(model)), settings_(settings) {}

void FrameBudget::reset() {
    std::fill(step_.begin(), step_.end(), std::uint8_t{0});
    std::fill(seen_.begin(), seen_.end(), 0u);
    std::fill(lowered_.begin(), lowered_.end(), 0u);
}

void FrameBudget::ensureState(const Scene& scene) {
    if (scene_ == &scene && alternatives_.nodeCount() == scene.nodeCount()) return;
    if (scene_ != &scene) {
        step_.clear();
        seen_.clear();
        lowered_.clear();
    }
    scene_ = &scene;
    alternatives_ = LodAlternatives(scene);
    step_.resize(scene.nodeCount(), 0);
    seen_.resize(scene.nodeCount(), 0);
    lowered_.resize(scene.nodeCount(), 0);
}

// Step 0 is the finest allowed level with the highest allowed shading; each
// step lowers shading, and past the lowest shading moves one level down with
// shading back at the highest: the paper's order of degradation.
std::uint8_t FrameBudget::levelAt(const Work& w, int step) const {
    return static_cast<std::uint8_t>(w.topLevel + step / w.shadingSpan);
}

Shading FrameBudget::shadingAt(const Work& w, int step) const {
    return static_cast<Shading>(w.topShading - step % w.shadingSpan);
}

double FrameBudget::costAt(const Work& w, int step, float pixels) const {
    return model_.itemMs(levelAt(w, step), shadingAt(w, step), pixels);
}

BudgetStats FrameBudget::apply(const Scene& scene, DrawList& list, const View& view, glm::vec3 gaze) {
    ensureState(scene);
    ++frame_;
    const glm::vec3 towards = glm::length(gaze) > 0.0f ? gaze : view.forward;
    const std::size_t n = list.items.size();
    work_.resize(n);
    pixels_.resize(n);
    double total = 0.0;
    for (std::uint32_t i = 0; i < n; ++i) {
        const DrawItem& item = list.items[i];
        Work& w = work_[i];
        w.item = i;
        w.object = alternatives_.object(item.node);
        const Sphere& bound = scene.worldBound(item.node);
        const float k1 = eccentricityAcuity(angleDegrees(towards, bound.center - view.eye), settings_.acuity);
        const float floor = settings_.eccentricityFloor;
        pixels_[i] = onScreenPixels(item, scene, view);
        w.importance = pixels_[i] * (floor + (1.0f - floor) * k1);
        w.topLevel = item.level;
        w.topShading = static_cast<std::uint8_t>(item.shading);
        w.shadingSpan = settings_.changeShading ? static_cast<std::uint8_t>(w.topShading + 1) : 1;
        // A cross-fading item shows two levels at once; moving one of them
        // would break the fade, so it keeps its level.
        const int levels = settings_.changeLevel && item.fade >= 1.0f ? alternatives_.levelCount(item.node) : 1;
        const int coarser = std::max(0, levels - 1 - static_cast<int>(item.level));
        w.maxStep = static_cast<std::uint8_t>((coarser + 1) * w.shadingSpan - 1);
        const bool seenLastFrame = seen_[w.object] + 1 == frame_;
        w.step = seenLastFrame ? std::min(step_[w.object], w.maxStep) : 0;
        w.cost = costAt(w, w.step, pixels_[i]);
        total += w.cost;
    }
    order_.resize(n);
    std::iota(order_.begin(), order_.end(), 0u);
    std::sort(order_.begin(), order_.end(),
              [&](std::uint32_t a, std::uint32_t b) { return work_[a].importance < work_[b].importance; });

    // Work in the calibrated table's units: predicted = gain · total + offset.
    const double gain = model_.gain();
    const double limit = (settings_.targetMs - model_.offset()) / gain;
    const double raiseLimit = (settings_.targetMs * (1.0 - settings_.upgradeMargin) - model_.offset()) / gain;
    stats_.stepsDown = stats_.stepsUp = 0;

    // Too slow: least important first, each as far down as needed.
    for (std::size_t k = 0; k < n && total > limit; ++k) {
        Work& w = work_[order_[k]];
        while (total > limit && w.step < w.maxStep) {
            const double c = costAt(w, w.step + 1, pixels_[w.item]);
            total += c - w.cost;
            w.cost = c;
            ++w.step;
            ++stats_.stepsDown;
            lowered_[w.object] = frame_;
        }
    }
    // Time to spare: most important first, each as far up as fits.
    const auto hold = static_cast<std::uint32_t>(std::max(settings_.holdFrames, 0));
    for (std::size_t k = n; k-- > 0;) {
        Work& w = work_[order_[k]];
        if (lowered_[w.object] != 0 && frame_ - lowered_[w.object] < std::max(hold, 1u)) continue;
        while (w.step > 0) {
            const double c = costAt(w, w.step - 1, pixels_[w.item]);
            if (total - w.cost + c > raiseLimit) break;
            total += c - w.cost;
            w.cost = c;
            --w.step;
            ++stats_.stepsUp;
        }
    }

    double weighted = 0.0, area = 0.0;
    stats_.itemsReduced = 0;
    for (const Work& w : work_) {
        DrawItem& item = list.items[w.item];
        const std::uint8_t level = levelAt(w, w.step);
        if (level != item.level) {
            item.node = alternatives_.levelNode(item.node, level);
            item.part = scene.meshPart(item.node);
            item.level = level;
        }
        item.shading = shadingAt(w, w.step);
        step_[w.object] = w.step;
        seen_[w.object] = frame_;
        const double rank = w.maxStep == 0 ? 1.0 : 1.0 - static_cast<double>(w.step) / w.maxStep;
        weighted += rank * pixels_[w.item];
        area += pixels_[w.item];
        stats_.itemsReduced += w.step > 0;
    }
    stats_.quality = area > 0.0 ? weighted / area : 1.0;
    stats_.targetMs = settings_.targetMs;
    lastItemsMs_ = total;
    lastPredictedMs_ = model_.frameMs(total);
    stats_.predictedMs = lastPredictedMs_;
    return stats_;
}

void FrameBudget::observe(double measuredMs) {
    stats_.measuredMs = measuredMs;
    stats_.measuredPredictedMs = lastPredictedMs_;
    model_.observe(lastItemsMs_, measuredMs);
}

}  // namespace arcomp
