#include "graph/core/ObjectMotion.hpp"

#include <cmath>

namespace arcomp {

namespace {

// Distance travelled along the line, folded into [0, range] (a triangle wave).
double travelled(const ObjectMotion& m, double t, double& direction) {
    const double speed = glm::length(m.velocity);
    direction = 1.0;
    if (m.range <= 0.0f || speed == 0.0) return speed * t;
    const double period = 2.0 * m.range;
    double s = std::fmod(speed * t, period);
    if (s < 0.0) s += period;
    if (s > m.range) {
        direction = -1.0;
        return period - s;
    }
    return s;
}

}  // namespace

glm::vec3 motionOffset(const ObjectMotion& m, double t) {
    const float speed = glm::length(m.velocity);
    if (speed == 0.0f) return glm::vec3(0.0f);
    double direction = 1.0;
    return m.velocity / speed * static_cast<float>(travelled(m, t, direction));
}

glm::vec3 motionVelocity(const ObjectMotion& m, double t) {
    double direction = 1.0;
    travelled(m, t, direction);
    return m.velocity * static_cast<float>(direction);
}

}  // namespace arcomp
