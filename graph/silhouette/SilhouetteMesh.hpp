#pragma once
// A mesh with one reduced index list per viewpoint region, all indexing one
// shared vertex buffer (paper: silhouette-preserving-reduction, section
// 2.4: the geometry stays on the GPU, only the index range changes).
//
//   SilhouetteMesh m = bakeSilhouetteMesh(positions, indices, regions);
//   SilhouetteRange r = m.rangeFor(eye);   // the region holding the eye, else the full mesh
//   draw(m.indices, r.firstIndex, r.indexCount);
//
// `indices` holds the full mesh first, then each region's list in order.

#include "graph/core/Geometry.hpp"
#include "graph/silhouette/SilhouetteReduction.hpp"
#include "graph/silhouette/ViewRegion.hpp"

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace arcomp {

struct SilhouetteRange {
    std::uint32_t firstIndex = 0;
    std::uint32_t indexCount = 0;
};

struct SilhouetteRegionReport {
    std::size_t front = 0, back = 0, silhouette = 0, backKept = 0, frontAfter = 0, frontLocked = 0;
    int rejectedTries = 0;
    std::size_t trianglesBefore = 0, trianglesAfter = 0;
};

struct SilhouetteMesh {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;
    SilhouetteRange full;
    std::vector<ViewRegion> regions;
    std::vector<SilhouetteRange> ranges;  // one per region

    // The first region holding `eye` (regions may touch), or -1.
    int regionAt(const glm::vec3& eye) const;
    SilhouetteRange rangeFor(const glm::vec3& eye) const;
    std::span<const std::uint32_t> indicesOf(SilhouetteRange r) const {
        return std::span(indices).subspan(r.firstIndex, r.indexCount);
    }
    // Positions and every index list as one Geometry, for the scene.
    Geometry geometry() const;
};

// One vertex per distinct position, indices remapped, triangles that weld
// to a line or point dropped: the surface bakeSilhouetteMesh works on.
struct FlatWeld {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;
};
FlatWeld weldPositions(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices);

using BakeProgress = std::function<void(std::size_t regionsDone, std::size_t regionCount)>;

// Welds equal positions first (so that borders and holes are found on the
// surface, not on split vertices), then reduces the mesh for every region,
// regions in parallel. `progress` is called under a lock, from any thread.
SilhouetteMesh bakeSilhouetteMesh(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
                                  std::vector<ViewRegion> regions,
                                  std::vector<SilhouetteRegionReport>* report = nullptr,
                                  const BakeProgress& progress = {});

}  // namespace arcomp
