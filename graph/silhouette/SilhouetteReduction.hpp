#pragma once
// The reduced mesh for one viewpoint region (paper:
// silhouette-preserving-reduction, section 2.4): FM simplified with its
// border locked, BM discarded, SM kept as it is.
//
//   const MeshHoles holes = findHoles(positions, indices);
//   RegionReduction r = reduceForRegion(positions, indices, region, holes);
//   // r.indices index `positions`, the same buffer the full mesh uses
//
// What is guaranteed, and checked on every result (not assumed from the
// simplifier): for every eye e in the region, outside the mesh's solid and
// with the whole mesh in front of e (a pinhole camera at e), the set of image points covered by the reduced mesh equals
// the set covered by the full mesh, except possibly on the projected curves of FM's border (which lie on SM or on the
// outline). Why:
// - Every simplified FM triangle is strictly front-facing from every region
//   vertex, hence (the region being convex) from every e in it; and the
//   simplified FM has the same oriented border chain as FM. A 2-chain whose
//   triangles all face e covers exactly the points that its border winds
//   around (the degree of the projection is the winding number), so the
//   simplified FM covers what FM covered: it can neither shrink nor reach
//   outside the silhouette. A result failing either check is rejected; the
//   FM triangles around the failure are then locked (kept as they are) and
//   the rest simplified again, down to keeping FM whole.
// - BM triangles face away from every e. On a closed mesh the first surface a
//   ray meets faces it, so BM adds no coverage and is dropped. On an open
//   mesh a BM triangle can be seen through a hole; a point seen only through
//   back faces has a nonzero winding of the hole borders around it, so the
//   line from e through it meets a hole's bounding sphere. BM triangles for
//   which that can happen from some e in the region are kept
//   (conservatively, through bounding spheres); the others are dropped.

#include "graph/core/Bounds.hpp"
#include "graph/silhouette/FacingClass.hpp"
#include "graph/silhouette/ViewRegion.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace arcomp {

// Border loops of an open mesh, each as a bounding sphere; empty when the
// mesh is closed.
struct MeshHoles {
    std::vector<Sphere> spheres;
    std::size_t borderEdges = 0;
};

MeshHoles findHoles(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices);

struct RegionReduction {
    std::vector<std::uint32_t> indices;
    std::size_t front = 0, back = 0, silhouette = 0;
    std::size_t backKept = 0;     // BM triangles kept because of holes
    std::size_t frontAfter = 0;   // FM triangles after simplification
    std::size_t frontLocked = 0;  // FM triangles locked after a rejected try
    int rejectedTries = 0;
    std::size_t trianglesBefore() const { return front + back + silhouette; }
    std::size_t trianglesAfter() const { return indices.size() / 3; }
};

struct ReductionSettings {
    float targetError = 0.05f;  // meshoptimizer's relative error; the checks, not this, keep the silhouette
    int maxTries = 16;
    int triesPerRing = 3;
};

RegionReduction reduceForRegion(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
                                const ViewRegion& region, const MeshHoles& holes,
                                const ReductionSettings& settings = {});

// The two checks above, exposed for tests: the oriented border chain of a
// triangle list as sorted (from, to) pairs, and whether every triangle is
// strictly front-facing from every point.
std::vector<std::pair<std::uint32_t, std::uint32_t>> borderChain(std::span<const std::uint32_t> indices);
bool allFrontFacing(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
                    std::span<const glm::vec3> eyes);

}  // namespace arcomp
