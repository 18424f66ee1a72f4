#include "graph/lod/Lod.hpp"
#include "graph/core/Check.hpp"

#include <algorithm>
#include <cstdlib>
#include <limits>

namespace arcomp {

void LodNode::setThresholds(std::initializer_list<float> t) {
    ARCOMP_CHECK(t.size() + 1 <= kMaxLodLevels, "an LOD node has at most kMaxLodLevels levels");
    std::copy(t.begin(), t.end(), thresholds.begin());
    levelCount = static_cast<std::uint8_t>(t.size() + 1);
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

LodChoice LodTable::fade(std::uint32_t i, std::uint8_t previous, std::uint8_t level, bool fresh, double timeSeconds) {
    if (previous != kNoLevel && previous != level) {
        fadeFrom_[i] = previous;
        fadeStart_[i] = timeSeconds;
    }
    if (fresh) fadeFrom_[i] = kNoLevel;
    if (fadeFrom_[i] == kNoLevel) return {level, kNoLevel, 1.0f};
    const double t = (timeSeconds - fadeStart_[i]) / nodes_[i].fadeSeconds;
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
