#pragma once
// The six planes of a view frustum, for sphere tests in the select pass.
//
//   Frustum f = Frustum::fromViewProjection(proj * view);
//   switch (f.classify(sphere)) { case Containment::Outside: ... }

#include "graph/core/Bounds.hpp"

#include <array>

namespace arcomp {

enum class Containment : unsigned char { Outside, Intersects, Inside };

struct Frustum {
    // Normals point inwards: dot(n, p) + d >= 0 inside.
    std::array<glm::vec4, 6> planes{};

    static Frustum fromViewProjection(const glm::mat4& viewProjection);

    Containment classify(const Sphere& s) const {
        if (s.empty()) return Containment::Outside;
        Containment result = Containment::Inside;
        for (const glm::vec4& p : planes) {
            const float distance = p.x * s.center.x + p.y * s.center.y + p.z * s.center.z + p.w;
            if (distance < -s.radius) return Containment::Outside;
            if (distance < s.radius) result = Containment::Intersects;
        }
        return result;
    }
};

} // namespace arcomp
