#pragma once
// A procedurally grown tree for translucent point-cloud tests and scenes:
// a tapering trunk that branches four levels deep, with clusters of small
// flat leaves at the twig tips. The same seed always grows the same tree.
//
//   const ProceduralTree tree = growTree(2009);
//   VoxelGrid grid = voxelize(tree.voxelSources(), 200);   // about 46k voxels
//
// The tree stands on the origin, about 2.6 units tall; wood is grey-brown
// and leaves green, both with alpha below one.

#include "graph/core/Geometry.hpp"
#include "graph/points/Voxelizer.hpp"

#include <cstdint>
#include <vector>

namespace arcomp {

struct ProceduralTree {
    Geometry wood, leaves;
    glm::vec4 woodColor{0.47f, 0.40f, 0.33f, 0.85f};
    glm::vec4 leafColor{0.22f, 0.62f, 0.18f, 0.55f};

    // Wood and leaves in the tree's own space, each with its colour. The
    // sources point into this tree: keep it alive while they are used.
    std::vector<VoxelSource> voxelSources() const;
};

ProceduralTree growTree(std::uint32_t seed = 2009);

}  // namespace arcomp
