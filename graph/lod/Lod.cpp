#include "graph/lod/Lod.hpp"
#include "graph/core/Check.hpp"

#include <algorithm>
#include <cstdlib>
#include <limits>

namespace arcomp {

namespace {

// A node unseen for longer than this starts afresh: no band around its old
// level, no fade from it, no angular speed over the gap.
constexpr double kStaleSeconds = 0.25;

bool ascending(LodPolicy p) { return p == LodPolicy::Distance; }

} // namespace

void LodNode::setThresholds(std::initializer_list<float> t) {
    ARCOMP_CHECK(t.size() + 1 <= kMaxLodLevels, "an LOD node has at most kMaxLodLevels levels");
    std::copy(t.begin(), t.end(), thresholds.begin());
    levelCount = static_cast<std::uint8_t>(t.size() + 1);
}

float lodMetric(LodPolicy policy, const LodInputs& in) {
    switch (policy) {
    case LodPolicy::Distance: return in.distance;
    case LodPolicy::ScreenSize: return in.pixels;
    case LodPolicy::GazeAcuity: return in.acuity;
    case LodPolicy::ScreenSizeTimesAcuity: return in.pixels * in.acuity;
    }
    return 0.0f;
}

std::uint8_t chooseLevel(const LodNode& node, float metric, std::uint8_t previous) {
    const bool up = ascending(node.policy);
    std::uint8_t level = 0;
    for (std::uint8_t i = 0; i + 1 < node.levelCount; ++i) {
        float t = node.thresholds[i];
        if (previous != kNoLevel) {
            // Boundary i separates levels ≤ i (finer) from > i (coarser).
            // Shown on the fine side: coarsening needs the band crossed too.
            const bool wasFine = previous <= i;
            const float band = node.hysteresis * t;
            t += (wasFine == up) ? band : -band;
        }
        const bool coarser = up ? metric >= t : metric < t;
        if (!coarser) break;
        level = static_cast<std::uint8_t>(i + 1);
    }
    return level;
}

std::uint32_t LodTable::add(const LodNode& node) {
    nodes_.push_back(node);
    level_.push_back(kNoLevel);
    fadeFrom_.push_back(kNoLevel);
    fadeStart_.push_back(0.0);
    lastChosen_.push_back(-std::numeric_limits<double>::infinity());
    tracked_.push_back({});
    trackedAt_.push_back(0.0);
    return static_cast<std::uint32_t>(nodes_.size() - 1);
}

void LodTable::reset() {
    std::fill(level_.begin(), level_.end(), kNoLevel);
    std::fill(fadeFrom_.begin(), fadeFrom_.end(), kNoLevel);
    std::fill(lastChosen_.begin(), lastChosen_.end(), -std::numeric_limits<double>::infinity());
    std::fill(tracked_.begin(), tracked_.end(), TrackedPoint{});
}

LodChoice LodTable::choose(std::uint32_t i, const LodInputs& in, double timeSeconds) {
    const LodNode& n = nodes_[i];
    const bool fresh = timeSeconds - lastChosen_[i] > kStaleSeconds;
    const std::uint8_t previous = fresh ? kNoLevel : level_[i];
    const std::uint8_t level = chooseLevel(n, lodMetric(n.policy, in), previous);
    lastChosen_[i] = timeSeconds;
    level_[i] = level;

    if (n.fadeSeconds <= 0.0f) return {level, kNoLevel, 1.0f};
    if (previous != kNoLevel && previous != level) {
        fadeFrom_[i] = previous;
        fadeStart_[i] = timeSeconds;
    }
    if (fresh) fadeFrom_[i] = kNoLevel;
    if (fadeFrom_[i] == kNoLevel) return {level, kNoLevel, 1.0f};
    const double t = (timeSeconds - fadeStart_[i]) / n.fadeSeconds;
    if (t >= 1.0) {
        fadeFrom_[i] = kNoLevel;
        return {level, kNoLevel, 1.0f};
    }
    return {level, fadeFrom_[i], static_cast<float>(std::max(t, 0.0))};
}

float LodTable::acuity(std::uint32_t i, const glm::mat4& world, const glm::vec3& eye, const glm::vec3& gaze,
                       double timeSeconds) {
    const LodNode& n = nodes_[i];
    const glm::vec3 center = glm::vec3(world * glm::vec4(n.center, 1.0f));
    const float theta = angleDegrees(gaze, center - eye);
    const double dt = timeSeconds - trackedAt_[i];
    const bool continuous = tracked_[i].valid && dt > 0.0 && dt <= kStaleSeconds;
    const float speed = continuous ? angularSpeed(tracked_[i], world, eye, static_cast<float>(dt)) : 0.0f;
    tracked_[i] = trackPoint(eye, world, n.center, n.meanRadius);
    trackedAt_[i] = timeSeconds;
    return gazeAcuity(theta, speed, n.acuity);
}

} // namespace arcomp
