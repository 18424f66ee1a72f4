#include "graph/core/Bounds.hpp"

#include <algorithm>
#include <cmath>

namespace arcomp {

Box boxAround(std::span<const glm::vec3> points) {
    Box b;
    for (const glm::vec3& p : points) b.expand(p);
    return b;
}

Sphere sphereAround(std::span<const glm::vec3> points) {
    const Box b = boxAround(points);
    if (b.empty()) return {};
    Sphere s{b.center(), 0.0f};
    float r2 = 0.0f;
    for (const glm::vec3& p : points) {
        const glm::vec3 d = p - s.center;
        r2 = std::max(r2, glm::dot(d, d));
    }
    s.radius = std::sqrt(r2);
    return s;
}

Sphere sphereAround(const Box& box) {
    if (box.empty()) return {};
    return {box.center(), glm::length(box.max - box.min) * 0.5f};
}

Sphere transformed(const Sphere& s, const glm::mat4& m) {
    if (s.empty()) return s;
    const float sx = glm::dot(glm::vec3(m[0]), glm::vec3(m[0]));
    const float sy = glm::dot(glm::vec3(m[1]), glm::vec3(m[1]));
    const float sz = glm::dot(glm::vec3(m[2]), glm::vec3(m[2]));
    const float scale = std::sqrt(std::max({sx, sy, sz}));
    return {glm::vec3(m * glm::vec4(s.center, 1.0f)), s.radius * scale};
}

Box transformed(const Box& b, const glm::mat4& m) {
    if (b.empty()) return b;
    Box out;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner{(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z};
        out.expand(glm::vec3(m * glm::vec4(corner, 1.0f)));
    }
    return out;
}

bool contains(const Sphere& outer, const Sphere& inner, float slack) {
    if (inner.empty()) return true;
    if (outer.empty()) return false;
    return glm::length(inner.center - outer.center) + inner.radius <= outer.radius * (1.0f + slack) + slack;
}

Sphere merged(const Sphere& a, const Sphere& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    const glm::vec3 d = b.center - a.center;
    const float dist = glm::length(d);
    if (dist + b.radius <= a.radius) return a;
    if (dist + a.radius <= b.radius) return b;
    const float radius = (dist + a.radius + b.radius) * 0.5f;
    // Move from a's centre towards b so that both far ends touch the result.
    const glm::vec3 center = a.center + d * ((radius - a.radius) / dist);
    return {center, radius};
}

}  // namespace arcomp
