#include "graph/core/View.hpp"
#include "graph/core/DiscArea.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace arcomp {

float View::pixelScale() const { return static_cast<float>(viewport.y) * 0.5f / std::tan(fovyRadians * 0.5f); }

float View::projectedArea(const Sphere& s) const {
    if (s.empty()) return 0.0f;
    const glm::vec3 toCenter = s.center - eye;
    return projectedDiscArea(s.radius, glm::dot(toCenter, toCenter), pixelScale(),
                             static_cast<float>(viewport.x) * static_cast<float>(viewport.y));
}

View View::lookAt(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up, float fovyDegrees,
                  glm::ivec2 viewport, float near, float far) {
    View v;
    v.eye = eye;
    v.forward = glm::normalize(target - eye);
    glm::vec3 safeUp = up;
    if (std::abs(glm::dot(glm::normalize(up), v.forward)) > 0.999f) safeUp = {0.0f, 0.0f, 1.0f};
    v.view = glm::lookAt(eye, target, safeUp);
    v.fovyRadians = glm::radians(fovyDegrees);
    v.viewport = viewport;
    v.near = near;
    v.far = far;
    const float aspect = static_cast<float>(viewport.x) / static_cast<float>(std::max(1, viewport.y));
    v.projection = glm::perspective(v.fovyRadians, aspect, near, far);
    return v;
}

View View::framing(const Sphere& s, float fovyDegrees, glm::ivec2 viewport) {
    const Sphere target = s.empty() ? Sphere{glm::vec3(0.0f), 1.0f} : s;
    const float radius = std::max(target.radius, 1e-6f);
    const float halfFov = glm::radians(fovyDegrees) * 0.5f;
    const float distance = radius / std::sin(halfFov) / 0.8f;
    const glm::vec3 direction = glm::normalize(glm::vec3(0.0f, 0.25f, 1.0f));
    return lookAt(target.center + direction * distance, target.center, {0.0f, 1.0f, 0.0f}, fovyDegrees, viewport,
                  std::max(distance - radius * 1.5f, distance * 0.01f), distance + radius * 1.5f);
}

}  // namespace arcomp
