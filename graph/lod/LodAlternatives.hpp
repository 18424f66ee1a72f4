#pragma once
// For each mesh that is one level of an LOD node, the meshes of that node's
// other levels: what the frame-time controller needs to move a drawn item to
// a coarser or finer level without walking the scene again.
//
//   LodAlternatives alts(scene);                 // after scene.update()
//   if (alts.levelCount(item.node) > 2) item.node = alts.levelNode(item.node, 2);
//
// Only LOD nodes whose every level is a single mesh (what addGeneratedLod
// and `arcomp bake lod` make) have alternatives; a level that is a whole
// subtree keeps the level the select pass chose.

#include "graph/core/Scene.hpp"

#include <vector>

namespace arcomp {

class LodAlternatives {
public:
    LodAlternatives() = default;
    explicit LodAlternatives(const Scene& scene);

    // Levels of the LOD node that `mesh` is a level of; 1 when it is none.
    std::uint8_t levelCount(NodeId mesh) const;
    // The mesh node of level `level` of the same LOD node; `mesh` itself
    // when it has no alternatives.
    NodeId levelNode(NodeId mesh, std::uint8_t level) const;
    // The same object whatever level is drawn: level 0's mesh node.
    NodeId object(NodeId mesh) const { return levelNode(mesh, 0); }
    // The scene's node count when this was built, to notice a changed scene.
    std::size_t nodeCount() const { return group_.size(); }

private:
    static constexpr std::uint32_t kNone = ~std::uint32_t{0};
    std::vector<std::uint32_t> group_;       // per node: index into groupStart_, or kNone
    std::vector<std::uint32_t> groupStart_;  // offsets into levels_, one past the end last
    std::vector<NodeId> levels_;             // every group's level meshes, finest first
};

}  // namespace arcomp
