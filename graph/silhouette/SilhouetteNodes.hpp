#pragma once
// The side table behind NodeKind::SilhouetteRegion nodes: per node, the
// scene geometry holding a SilhouetteMesh's shared buffer (all index lists
// in one), its regions in the node's local space and their index ranges.
// The select pass picks the range of the region holding the eye, the full
// mesh's range outside every region.
//
//   NodeId n = addSilhouetteNode(world.scene, parent, world.silhouettes, mesh, material);
//   select(world, view, {}, list);   // items carry firstIndex/indexCount

#include "graph/core/Scene.hpp"
#include "graph/silhouette/SilhouetteMesh.hpp"

#include <vector>

namespace arcomp {

struct SilhouetteNode {
    MeshPart part;
    SilhouetteRange full;
    std::vector<ViewRegion> regions;
    std::vector<SilhouetteRange> ranges;

    SilhouetteRange rangeFor(const glm::vec3& localEye) const;
};

struct SilhouetteNodes {
    std::vector<SilhouetteNode> nodes;
};

NodeId addSilhouetteNode(Scene& scene, NodeId parent, SilhouetteNodes& table, const SilhouetteMesh& mesh,
                         std::uint32_t material, std::string name = {});

}  // namespace arcomp
