#pragma once
// Classifies triangles against a viewpoint region (paper:
// silhouette-preserving-reduction, section 2.2-2.3): FM when front-facing
// from every point of the region, BM when back-facing from every point, SM
// otherwise. Because the region is convex, its vertices decide: the sign of
// the plane test is linear along any segment between two of them.
//
//   std::vector<Facing> f = classifyTriangles(positions, indices, region.vertices());
//
// An eye on a triangle's plane (within a relative tolerance) counts as
// neither front nor back, so the triangle lands in SM: the conservative side.

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace arcomp {

enum class Facing : std::uint8_t { Front, Back, Silhouette };

// Strictly front-facing from `eye` (counter-clockwise seen from it), with the
// on-plane band counted as not front-facing.
bool frontFacingFrom(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& eye);
bool backFacingFrom(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& eye);

// Paper, equations (1)-(3), decided on the region's vertices alone.
Facing classifyTriangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                        std::span<const glm::vec3> regionVertices);

std::vector<Facing> classifyTriangles(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
                                      std::span<const glm::vec3> regionVertices);

}  // namespace arcomp
