#pragma once
// A viewpoint region: a convex polytope in which the viewer's eye may stand
// (DESIGN.md section 4). It keeps its vertices, which classification tests
// against, and the planes of their convex hull, which answer "is the eye in
// here?".
//
//   ViewRegion r = ViewRegion::fromBox({{-1, 0, 3}, {1, 2, 5}});
//   ViewRegion q = ViewRegion::fromVertices(points);   // hull computed here
//   if (r.contains(eye)) ...
//
// fromVertices drops points inside the hull from vertices() (they add nothing
// to classification) and throws std::invalid_argument when
// the points span no volume or are more than kMaxRegionVertices.

#include "graph/core/Bounds.hpp"

#include <span>
#include <vector>

namespace arcomp {

// Points x with dot(normal, x) <= offset are inside; normal is unit length.
struct Plane {
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    float offset = 0.0f;

    float distance(const glm::vec3& p) const { return glm::dot(normal, p) - offset; }
};

inline constexpr std::size_t kMaxRegionVertices = 64;

class ViewRegion {
public:
    static ViewRegion fromBox(const Box& box);
    static ViewRegion fromVertices(std::span<const glm::vec3> points);

    std::span<const glm::vec3> vertices() const { return vertices_; }
    std::span<const Plane> planes() const { return planes_; }
    // Inside or on the boundary, up to `slack` world units outside.
    bool contains(const glm::vec3& p, float slack = 1e-5f) const;
    Box box() const { return boxAround(vertices_); }

private:
    std::vector<glm::vec3> vertices_;
    std::vector<Plane> planes_;
};

// `count` boxes, each one bounding radius wide, around the sphere: centres
// at azimuths 360/count degrees apart, alternately 25 degrees above and
// below the centre, at distances spread evenly from 3 to 6 radii. The
// silhouette benchmark's default set.
std::vector<ViewRegion> regionsAround(const Sphere& bound, int count);

}  // namespace arcomp
