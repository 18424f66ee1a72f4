#include "graph/silhouette/FacingClass.hpp"

namespace arcomp {

namespace {

// Signed distance-like value of the eye above the triangle's plane, and the
// band within which the sign is not trusted (relative to the magnitudes, so
// that it holds for any model scale). Computed in double: the band is then
// far wider than the rounding of the inputs' products.
int sideOf(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& eye) {
    const glm::dvec3 da(a), db(b), dc(c), de(eye);
    const glm::dvec3 n = glm::cross(db - da, dc - da);
    const glm::dvec3 v = de - da;
    const double s = glm::dot(n, v);
    const double band = 1e-9 * glm::length(n) * glm::length(v);
    if (s > band) return 1;
    if (s < -band) return -1;
    return 0;
}

}  // namespace

bool frontFacingFrom(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& eye) {
    return sideOf(a, b, c, eye) > 0;
}

bool backFacingFrom(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& eye) {
    return sideOf(a, b, c, eye) < 0;
}

Facing classifyTriangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                        std::span<const glm::vec3> regionVertices) {
    bool allFront = true, allBack = true;
    for (const glm::vec3& e : regionVertices) {
        const int s = sideOf(a, b, c, e);
        allFront &= s > 0;
        allBack &= s < 0;
    }
    if (regionVertices.empty()) return Facing::Silhouette;
    if (allFront) return Facing::Front;
    if (allBack) return Facing::Back;
    return Facing::Silhouette;
}

std::vector<Facing> classifyTriangles(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
                                      std::span<const glm::vec3> regionVertices) {
    std::vector<Facing> out(indices.size() / 3);
    for (std::size_t t = 0; t < out.size(); ++t)
        out[t] = classifyTriangle(positions[indices[3 * t]], positions[indices[3 * t + 1]],
                                  positions[indices[3 * t + 2]], regionVertices);
    return out;
}

}  // namespace arcomp
