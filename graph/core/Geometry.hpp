#pragma once
// Triangle geometry as the renderer and the mesh tools see it: flat arrays,
// one index list of triangles. Normals are always present after
// finalize(); texture coordinates, tangents, colours and skin influences are
// optional (empty).
//
//   Geometry g;
//   g.positions = {...}; g.indices = {...};
//   g.finalize();   // computes missing normals and the bounds

#include "graph/core/Bounds.hpp"

#include <glm/gtc/type_precision.hpp>

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
    // Skin influences, glTF's JOINTS_0 and WEIGHTS_0: four joints (indices
    // into the skin's joint list) and their weights, which sum to 1; a joint
    // whose weight is 0 is 0.
    std::vector<glm::u16vec4> joints;
    std::vector<glm::vec4> weights;
    std::vector<std::uint32_t> indices;

    Box box;
    Sphere bound;
    // The tangents were computed (computeTangents) for a normal map, the
    // file had none: inspect reports it, and a cache may recompute them.
    bool tangentsGenerated = false;

    std::size_t triangleCount() const { return indices.size() / 3; }
    bool hasSkinInfluences() const {
        return !positions.empty() && joints.size() == positions.size() && weights.size() == positions.size();
    }
    // Computes area-weighted vertex normals when none were given and the
    // bounds; call once after filling the arrays.
    void finalize();
};

std::vector<glm::vec3> computeVertexNormals(const std::vector<glm::vec3>& positions,
                                            const std::vector<std::uint32_t>& indices);

// Tangents for a normal map, in the spirit of MikkTSpace: each triangle's
// tangent and bitangent from its UV derivatives, summed per vertex weighted
// by the corner angle, made perpendicular to the normal (Gram-Schmidt), with
// w the bitangent's sign as glTF's TANGENT has it. The bitangent points
// towards decreasing v, "up" in a glTF image, where a normal map's green
// channel points. Where the UVs give no direction (a degenerate or
// unmapped vertex) the tangent is some unit vector perpendicular to the
// normal, w = +1: never NaN. `normals` must be unit length, one per position.
std::vector<glm::vec4> computeTangents(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                                       const std::vector<glm::vec2>& texcoords,
                                       const std::vector<std::uint32_t>& indices);

// A UV sphere of the given radius; used for generated scenes and benchmarks.
Geometry makeUvSphere(float radius, int slices, int stacks);
// An axis-aligned box centred on the origin.
Geometry makeBox(const glm::vec3& size);

}  // namespace arcomp
