#include "graph/lod/GazeAcuity.hpp"

#include <algorithm>
#include <cmath>

namespace arcomp {

// Paper: gaze-directed-lod, eq. (1): k1 = 1 for θ ≤ a, exp(-(θ - a) / c1) beyond.
float eccentricityAcuity(float thetaDegrees, const GazeAcuityParams& p) {
    if (thetaDegrees <= p.foveaDegrees) return 1.0f;
    return std::exp(-(thetaDegrees - p.foveaDegrees) / p.c1Degrees);
}

// Paper: gaze-directed-lod, eq. (2): k2 = 1 - Δφ / c2 below c2, 0 from c2 on.
float motionAcuity(float angularSpeedDegreesPerSecond, const GazeAcuityParams& p) {
    const float speed = std::max(angularSpeedDegreesPerSecond, 0.0f);
    if (speed >= p.c2DegreesPerSecond) return 0.0f;
    return 1.0f - speed / p.c2DegreesPerSecond;
}

float angleDegrees(const glm::vec3& a, const glm::vec3& b) {
    const float la = glm::length(a);
    const float lb = glm::length(b);
    if (la <= 0.0f || lb <= 0.0f) return 0.0f;
    // atan2 of |a×b| and a·b keeps precision for small angles, where acos does not.
    const float angle = std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
    return glm::degrees(angle);
}

float meanRadius(std::span<const glm::vec3> positions, const glm::vec3& center) {
    if (positions.empty()) return 0.0f;
    double sum = 0.0;
    for (const glm::vec3& p : positions) sum += glm::length(p - center);
    return static_cast<float>(sum / static_cast<double>(positions.size()));
}

glm::vec3 representativePoint(const glm::vec3& eye, const glm::vec3& center, float meanRadius) {
    const glm::vec3 toEye = eye - center;
    const float distance = glm::length(toEye);
    if (distance <= meanRadius || distance <= 0.0f) return center;
    return center + toEye * (meanRadius / distance);
}

TrackedPoint trackPoint(const glm::vec3& eye, const glm::mat4& objectWorld, const glm::vec3& localCenter,
                        float meanRadius) {
    // The mean radius is in the object's units; under scale the world sphere
    // scales with the largest axis, as bounds do.
    const float scale = std::sqrt(std::max({glm::dot(glm::vec3(objectWorld[0]), glm::vec3(objectWorld[0])),
                                            glm::dot(glm::vec3(objectWorld[1]), glm::vec3(objectWorld[1])),
                                            glm::dot(glm::vec3(objectWorld[2]), glm::vec3(objectWorld[2]))}));
    const glm::vec3 center = glm::vec3(objectWorld * glm::vec4(localCenter, 1.0f));
    TrackedPoint t;
    t.world = representativePoint(eye, center, meanRadius * scale);
    t.local = glm::vec3(glm::inverse(objectWorld) * glm::vec4(t.world, 1.0f));
    t.eye = eye;
    t.valid = true;
    return t;
}

float angularSpeed(const TrackedPoint& previous, const glm::mat4& objectWorldNow, const glm::vec3& eyeNow,
                   float dtSeconds) {
    if (!previous.valid || dtSeconds <= 0.0f) return 0.0f;
    const glm::vec3 pointNow = glm::vec3(objectWorldNow * glm::vec4(previous.local, 1.0f));
    return angleDegrees(previous.world - previous.eye, pointNow - eyeNow) / dtSeconds;
}

}  // namespace arcomp
