#include "graph/lod/Lod.hpp"
#include "graph/core/Check.hpp"

#include <algorithm>
#include <cstdlib>
#include <limits>

namespace arcomp {

void LodRule::setThresholds(std::initializer_list<float> t) {
    ARCOMP_CHECK(t.size() + 1 <= kMaxLodLevels, "an LOD node has at most kMaxLodLevels levels");
    std::copy(t.begin(), t.end(), thresholds.begin());
    levelCount = static_cast<std::uint8_t>(t.size() + 1);
}

std::uint32_t LodTable::add(const LodNode& node) {
    const LodRule& rule = node;
    // Scenes add their nodes' rules in runs of one kind: the last few are
    // where a repeat is found.
    constexpr std::size_t kLookBack = 8;
    const auto lookBack = static_cast<std::ptrdiff_t>(std::min(rules_.size(), kLookBack));
    const auto repeat = std::find(rules_.end() - lookBack, rules_.end(), rule);
    const auto shared = static_cast<std::uint32_t>(repeat - rules_.begin());
    if (repeat == rules_.end()) rules_.push_back(rule);
    history_.push_back({.lastChosen = -std::numeric_limits<double>::infinity(), .rule = shared});
    fadeStart_.push_back(0.0);
    gaze_.push_back({node.center, node.meanRadius, node.acuity, {}});
    return static_cast<std::uint32_t>(history_.size() - 1);
}

LodNode LodTable::node(std::uint32_t i) const {
    LodNode n;
    static_cast<LodRule&>(n) = rule(i);
    n.center = gaze_[i].center;
    n.meanRadius = gaze_[i].meanRadius;
    n.acuity = gaze_[i].acuity;
    return n;
}

void LodTable::reset() {
    for (History& h : history_) {
        h.level = h.fadeFrom = kNoLevel;
        h.lastChosen = -std::numeric_limits<double>::infinity();
    }
    for (GazeShape& g : gaze_) g.tracked = {};
}

LodChoice LodTable::fade(std::uint32_t i, std::uint8_t previous, std::uint8_t level, bool fresh, double timeSeconds) {
    History& h = history_[i];
    double& fadeStart = fadeStart_[i];
    if (previous != kNoLevel && previous != level) {
        h.fadeFrom = previous;
        fadeStart = timeSeconds;
    }
    if (fresh) h.fadeFrom = kNoLevel;
    if (h.fadeFrom == kNoLevel) return {level, kNoLevel, 1.0f};
    const double t = (timeSeconds - fadeStart) / rule(i).fadeSeconds;
    if (t >= 1.0) {
        h.fadeFrom = kNoLevel;
        return {level, kNoLevel, 1.0f};
    }
    return {level, h.fadeFrom, static_cast<float>(std::max(t, 0.0))};
}

float LodTable::acuity(std::uint32_t i, const glm::mat4& world, const glm::vec3& eye, const glm::vec3& gaze,
                       double timeSeconds) {
    GazeShape& g = gaze_[i];
    const glm::vec3 center = glm::vec3(world * glm::vec4(g.center, 1.0f));
    const float theta = angleDegrees(gaze, center - eye);
    const double dt = timeSeconds - g.trackedAt;
    const bool continuous = g.tracked.valid && dt > 0.0 && dt <= kStaleSeconds;
    const float speed = continuous ? angularSpeed(g.tracked, world, eye, static_cast<float>(dt)) : 0.0f;
    g.tracked = trackPoint(eye, world, g.center, g.meanRadius);
    g.trackedAt = timeSeconds;
    return gazeAcuity(theta, speed, g.acuity);
}

}  // namespace arcomp
