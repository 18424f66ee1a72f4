#pragma once
// The six planes of a view frustum, for sphere tests in the select pass.
//
//   Frustum f = Frustum::fromViewProjection(proj * view);
//   switch (f.classify(sphere)) { case Containment::Outside: ... }
//   const RunContainment run = f.classifyRun(x, y, z, radius, 16);  // bit i: sphere i

#include "graph/core/Bounds.hpp"

#include <array>
#include <cstdint>

namespace arcomp {

enum class Containment : unsigned char { Outside, Intersects, Inside };

// Where each sphere of a run lies: bit i set in `outside` or `inside` for
// sphere i; neither means it intersects the frustum's boundary.
struct RunContainment {
    std::uint32_t outside = 0;
    std::uint32_t inside = 0;
};

struct Frustum {
    // Normals point inwards: dot(n, p) + d >= 0 inside.
    std::array<glm::vec4, 6> planes{};

    static constexpr std::uint32_t kMaxRun = 32;

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

    // classify() for `count` (at most kMaxRun) spheres stored as separate
    // arrays of centre coordinates and radii, eight at a time with the same
    // arithmetic, so with the same answers.
    RunContainment classifyRun(const float* x, const float* y, const float* z, const float* radius,
                               std::uint32_t count) const;
};

}  // namespace arcomp
