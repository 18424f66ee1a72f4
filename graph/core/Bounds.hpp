#pragma once
// Bounding volumes. A Sphere with a negative radius is empty: it encloses
// nothing, merges as the identity and is never visible.
//
//   Sphere s = sphereAround(positions);
//   Sphere w = transformed(s, world);      // conservative under scale
//   Sphere both = merged(a, b);            // smallest sphere holding a and b

#include <glm/glm.hpp>
#include <limits>
#include <span>

namespace arcomp {

struct Sphere {
    glm::vec3 center{0.0f};
    float radius = -1.0f;

    bool empty() const { return radius < 0.0f; }
};

struct Box {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{std::numeric_limits<float>::lowest()};

    bool empty() const { return min.x > max.x; }
    glm::vec3 center() const { return (min + max) * 0.5f; }
    glm::vec3 size() const { return empty() ? glm::vec3(0.0f) : max - min; }
    float volume() const {
        const glm::vec3 s = size();
        return s.x * s.y * s.z;
    }
    void expand(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void expand(const Box& b) {
        if (!b.empty()) {
            expand(b.min);
            expand(b.max);
        }
    }
};

Box boxAround(std::span<const glm::vec3> points);
// Centre of the box, radius to the farthest point: tighter than the box's
// half-diagonal for most scanned meshes and cheap to compute.
Sphere sphereAround(std::span<const glm::vec3> points);
Sphere sphereAround(const Box& box);
Sphere transformed(const Sphere& s, const glm::mat4& m);
Box transformed(const Box& b, const glm::mat4& m);
Sphere merged(const Sphere& a, const Sphere& b);
bool contains(const Sphere& outer, const Sphere& inner, float slack = 1e-4f);

}  // namespace arcomp
