#pragma once
// Triangle geometry as the renderer and the mesh tools see it: flat arrays,
// one index list of triangles. Normals are always present after
// finalize(); texture coordinates, tangents and colours are optional (empty).
//
//   Geometry g;
//   g.positions = {...}; g.indices = {...};
//   g.finalize();   // computes missing normals and the bounds

#include "graph/core/Bounds.hpp"

#include <cstdint>
#include <vector>

namespace arcomp {

struct Geometry {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> texcoords;   // TEXCOORD_0
    std::vector<glm::vec2> texcoords1;  // TEXCOORD_1
    std::vector<glm::vec4> tangents;    // xyz tangent, w the bitangent's sign (glTF's TANGENT)
    std::vector<glm::vec4> colors;
    std::vector<std::uint32_t> indices;

    Box box;
    Sphere bound;

    std::size_t triangleCount() const { return indices.size() / 3; }
    // Computes area-weighted vertex normals when none were given and the
    // bounds; call once after filling the arrays.
    void finalize();
};

std::vector<glm::vec3> computeVertexNormals(const std::vector<glm::vec3>& positions,
                                            const std::vector<std::uint32_t>& indices);

// A UV sphere of the given radius; used for generated scenes and benchmarks.
Geometry makeUvSphere(float radius, int slices, int stacks);
// An axis-aligned box centred on the origin.
Geometry makeBox(const glm::vec3& size);

} // namespace arcomp
