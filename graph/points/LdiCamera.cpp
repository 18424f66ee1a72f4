#include "graph/points/LdiCamera.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace arcomp {

glm::vec3 LdiCamera::rayDirection(int x, int y) const {
    const glm::vec2 c = principal();
    const glm::vec3 local((static_cast<float>(x) + 0.5f - c.x) / focal, (static_cast<float>(y) + 0.5f - c.y) / focal,
                          1.0f);
    return glm::normalize(glm::transpose(rotation) * local);
}

LdiCamera LdiCamera::lookAt(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up, float fovyDegrees,
                            int width, int height) {
    LdiCamera c;
    c.eye = eye;
    const glm::vec3 forward = glm::normalize(target - eye);
    glm::vec3 side = glm::cross(forward, up);
    if (glm::length(side) < 1e-6f)
        side = glm::cross(forward, std::abs(forward.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0));
    const glm::vec3 right = glm::normalize(side);
    const glm::vec3 down = glm::cross(forward, right);
    c.rotation = glm::transpose(glm::mat3(right, down, forward));
    c.width = width;
    c.height = height;
    c.focal = static_cast<float>(height) * 0.5f / std::tan(glm::radians(fovyDegrees) * 0.5f);
    return c;
}

std::vector<LdiCamera> ldiCamerasAround(const Sphere& bound, int count, float pixelSize) {
    if (count < 1 || count > 255) throw std::invalid_argument("ldiCamerasAround: count must lie in [1, 255]");
    if (!(pixelSize > 0.0f)) throw std::invalid_argument("ldiCamerasAround: pixel size must be > 0");
    std::vector<glm::vec3> directions;
    if (count == 1) {
        directions.push_back(glm::normalize(glm::vec3(0.0f, 0.25f, 1.0f)));
    } else if (count == 6) {
        directions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    } else {
        // Fibonacci sphere: even spread without a favoured axis.
        const float golden = std::numbers::pi_v<float> * (3.0f - std::sqrt(5.0f));
        for (int i = 0; i < count; ++i) {
            const float y = 1.0f - 2.0f * (static_cast<float>(i) + 0.5f) / static_cast<float>(count);
            const float r = std::sqrt(std::max(0.0f, 1.0f - y * y));
            const float a = golden * static_cast<float>(i);
            directions.emplace_back(r * std::cos(a), y, r * std::sin(a));
        }
    }
    const float radius = std::max(bound.radius, 1e-6f);
    const float fovy = 40.0f;
    const float halfFov = glm::radians(fovy) * 0.5f;
    const float distance = radius / std::sin(halfFov) * 1.05f;
    const int pixels =
        std::clamp(static_cast<int>(std::ceil(2.0f * distance * std::tan(halfFov) / pixelSize)), 8, 4096);
    std::vector<LdiCamera> cameras;
    for (const glm::vec3& d : directions)
        cameras.push_back(
            LdiCamera::lookAt(bound.center + d * distance, bound.center, {0, 1, 0}, fovy, pixels, pixels));
    return cameras;
}

}  // namespace arcomp
