#pragma once
// A whole model as one triangle list in model space: every part's
// positions moved by its node's transform and appended. Mesh tools (the
// silhouette bake, its benchmark) work on this, not on the scene.
//
//   FlatMesh m = flattenModel(parseObj("bunny.obj"));

#include "graph/io/ModelLoader.hpp"

#include <cstdint>
#include <vector>

namespace arcomp {

struct FlatMesh {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;
};

FlatMesh flattenModel(const ParsedModel& model);

// Plain meshoptimizer simplification of the whole mesh towards a triangle
// count, no border locked: what a user would otherwise pick, and the
// silhouette benchmark's baseline.
std::vector<std::uint32_t> simplifyToTriangles(std::span<const glm::vec3> positions,
                                               std::span<const std::uint32_t> indices, std::size_t triangles);

}  // namespace arcomp
