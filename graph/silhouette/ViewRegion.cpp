#include "graph/silhouette/ViewRegion.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace arcomp {

ViewRegion ViewRegion::fromBox(const Box& box) {
    if (box.empty() || box.min.x >= box.max.x || box.min.y >= box.max.y || box.min.z >= box.max.z)
        throw std::invalid_argument("view region box must have min < max on every axis");
    ViewRegion r;
    for (int i = 0; i < 8; ++i)
        r.vertices_.push_back(
            {(i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y, (i & 4) ? box.max.z : box.min.z});
    for (int axis = 0; axis < 3; ++axis) {
        glm::vec3 n(0.0f);
        n[axis] = 1.0f;
        r.planes_.push_back({n, box.max[axis]});
        r.planes_.push_back({-n, -box.min[axis]});
    }
    return r;
}

// The hull by brute force: a triple of points spans a face plane when no
// point lies outside it. With at most kMaxRegionVertices points that is at
// most 64^4 cheap tests, run once per region at load time.
ViewRegion ViewRegion::fromVertices(std::span<const glm::vec3> points) {
    if (points.size() < 4) throw std::invalid_argument("view region needs at least 4 vertices");
    if (points.size() > kMaxRegionVertices)
        throw std::invalid_argument("view region has " + std::to_string(points.size()) + " vertices; at most " +
                                    std::to_string(kMaxRegionVertices) + " are allowed");
    for (const glm::vec3& p : points)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw std::invalid_argument("view region vertex is not finite");
    const Box box = boxAround(points);
    const double extent = glm::length(box.size());
    const double tol = 1e-6 * extent;
    const std::size_t n = points.size();
    std::vector<glm::dvec3> p(points.begin(), points.end());
    std::vector<char> onHull(n, 0);
    ViewRegion r;
    std::vector<glm::dvec4> planes;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
            for (std::size_t k = j + 1; k < n; ++k) {
                glm::dvec3 normal = glm::cross(p[j] - p[i], p[k] - p[i]);
                const double len = glm::length(normal);
                if (len <= 1e-12 * extent * extent) continue;
                normal /= len;
                double offset = glm::dot(normal, p[i]);
                bool above = false, below = false;
                for (std::size_t m = 0; m < n; ++m) {
                    const double d = glm::dot(normal, p[m]) - offset;
                    above |= d > tol;
                    below |= d < -tol;
                }
                if (above && below) continue;
                if (above) {
                    normal = -normal;
                    offset = -offset;
                }
                if (!above && !below) continue;  // all coplanar: no volume, caught below
                bool known = false;
                for (const glm::dvec4& q : planes)
                    known |= glm::dot(glm::dvec3(q), normal) > 1.0 - 1e-9 && std::abs(q.w - offset) <= tol;
                if (!known) planes.push_back({normal, offset});
                for (std::size_t m = 0; m < n; ++m)
                    if (std::abs(glm::dot(normal, p[m]) - offset) <= tol) onHull[m] = 1;
            }
    if (planes.size() < 4) throw std::invalid_argument("view region vertices span no volume");
    for (const glm::dvec4& q : planes) r.planes_.push_back({glm::vec3(q), static_cast<float>(q.w)});
    for (std::size_t m = 0; m < n; ++m)
        if (onHull[m]) r.vertices_.push_back(points[m]);
    return r;
}

bool ViewRegion::contains(const glm::vec3& p, float slack) const {
    for (const Plane& plane : planes_)
        if (plane.distance(p) > slack) return false;
    return !planes_.empty();
}

std::vector<ViewRegion> regionsAround(const Sphere& bound, int count) {
    std::vector<ViewRegion> out;
    const float r = bound.radius;
    for (int k = 0; k < count; ++k) {
        const float azimuth = glm::radians(360.0f * static_cast<float>(k) / static_cast<float>(count));
        const float elevation = glm::radians(k % 2 == 0 ? 25.0f : -25.0f);
        const float distance = count > 1 ? 3.0f + 3.0f * static_cast<float>(k) / static_cast<float>(count - 1) : 4.5f;
        const glm::vec3 dir(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                            std::cos(elevation) * std::cos(azimuth));
        const glm::vec3 c = bound.center + dir * distance * r;
        out.push_back(ViewRegion::fromBox({c - glm::vec3(0.5f * r), c + glm::vec3(0.5f * r)}));
    }
    return out;
}

}  // namespace arcomp
