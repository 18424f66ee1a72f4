#include "runtime/zones/Zone.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace arcomp {
namespace {

float cross(glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; }

float segmentDistance(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
    const glm::vec2 ab = b - a;
    const float length2 = glm::dot(ab, ab);
    const float t = length2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / length2, 0.0f, 1.0f) : 0.0f;
    return glm::length(p - (a + t * ab));
}

// Even-odd: a ray to +x crosses the edges an odd number of times inside.
bool insidePolygon(const std::vector<glm::vec2>& polygon, glm::vec2 p) {
    bool inside = false;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const glm::vec2 a = polygon[i], b = polygon[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
    }
    return inside;
}

// Whether segments ab and cd cross at a point inside both (touching ends
// of neighbouring edges do not count).
bool segmentsCross(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 d) {
    const float d1 = cross(b - a, c - a), d2 = cross(b - a, d - a), d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
    return ((d1 > 0.0f) != (d2 > 0.0f)) && ((d3 > 0.0f) != (d4 > 0.0f)) && d1 != 0.0f && d2 != 0.0f && d3 != 0.0f &&
           d4 != 0.0f;
}

}  // namespace

float defaultMargin(ZoneSpace space) { return space == ZoneSpace::Floor ? 0.15f : 0.02f; }

float signedDistance(const Zone& zone, glm::vec2 point) {
    if (zone.polygon.empty()) return glm::length(point - zone.center) - zone.radius;
    float nearest = std::numeric_limits<float>::max();
    for (std::size_t i = 0, j = zone.polygon.size() - 1; i < zone.polygon.size(); j = i++)
        nearest = std::min(nearest, segmentDistance(point, zone.polygon[j], zone.polygon[i]));
    return insidePolygon(zone.polygon, point) ? -nearest : nearest;
}

std::string polygonProblem(const std::vector<glm::vec2>& polygon) {
    if (polygon.size() < 3) return "has " + std::to_string(polygon.size()) + " corners; a polygon needs at least 3";
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = i + 2; k < n; ++k) {
            if (i == 0 && k == n - 1) continue;  // neighbours through the closing edge
            if (segmentsCross(polygon[i], polygon[(i + 1) % n], polygon[k], polygon[(k + 1) % n]))
                return "crosses itself: edge " + std::to_string(i + 1) + " (corners " + std::to_string(i + 1) + "-" +
                       std::to_string((i + 1) % n + 1) + ") crosses edge " + std::to_string(k + 1) + " (corners " +
                       std::to_string(k + 1) + "-" + std::to_string((k + 1) % n + 1) + ")";
        }
    float twiceArea = 0.0f, extent = 0.0f;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        twiceArea += cross(polygon[j], polygon[i]);
        extent = std::max(extent, glm::length(polygon[i] - polygon[0]));
    }
    if (std::abs(twiceArea) <= 1e-6f * std::max(extent * extent, 1e-12f))
        return "has no area: its corners lie on one line";
    return {};
}

std::vector<glm::vec2> samplePoints(const Zone& zone, int perSide) {
    glm::vec2 lo, hi;
    if (zone.polygon.empty()) {
        lo = zone.center - glm::vec2(zone.radius);
        hi = zone.center + glm::vec2(zone.radius);
    } else {
        lo = hi = zone.polygon[0];
        for (const glm::vec2& p : zone.polygon) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    }
    std::vector<glm::vec2> out = zone.polygon;
    for (int j = 0; j <= perSide; ++j)
        for (int i = 0; i <= perSide; ++i) {
            const glm::vec2 p = lo + (hi - lo) * glm::vec2(i, j) / static_cast<float>(perSide);
            if (signedDistance(zone, p) <= 0.0f) out.push_back(p);
        }
    return out;
}

}  // namespace arcomp
