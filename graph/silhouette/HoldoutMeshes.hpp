#pragma once
// The holdout geometry of a scene's CG meshes: per mesh node, the silhouette
// mesh (graph/silhouette/SilhouetteMesh.hpp) that cuts a person out of the video where
// that object stands in front of them. Its geometry lives in the CG scene
// itself, so one renderer draws both and the holdout follows the CG node's
// world matrix, its LOD level and the budget's choice of level.
//
//   world.holdouts.add(world.scene, meshNode, bakeSilhouetteMesh(positions, indices, regions), holdoutMaterial);
//   select(world, view, {}, list);   // list.holdouts: CG items that have one
//   // ... budget edits list.items ...
//   std::optional<DrawItem> cut = world.holdouts.itemFor(world.scene, list.items[list.holdouts[0].cgItem], view);
//
// An LOD node's levels are separate mesh nodes: each has its own entry, so
// the holdout of a coarser level is that level's silhouette.

#include "graph/core/DrawList.hpp"
#include "graph/core/View.hpp"
#include "graph/silhouette/SilhouetteNodes.hpp"

#include <optional>
#include <vector>

namespace arcomp {

class HoldoutMeshes {
public:
    // Adds `silhouette` (in `mesh`'s local space) as the holdout of mesh
    // node `mesh`, drawn with `material`. A second add for the same node
    // replaces the first.
    void add(Scene& scene, NodeId mesh, const SilhouetteMesh& silhouette, std::uint32_t material);
    // The holdout of a skinned mesh node: its own geometry, whole, with its
    // skin, so the renderer poses the holdout as it poses the CG. A silhouette
    // baked for the bind pose would not fit any other pose, and its welded
    // vertices would have lost their joints.
    void addPosed(const Scene& scene, NodeId mesh, std::uint32_t material);
    bool has(NodeId mesh) const { return mesh < slot_.size() && slot_[mesh] != kNone; }
    // The holdout item for a CG item whose node has an entry: the index
    // range of the region holding the eye (in the node's local space), the
    // full mesh outside every region; nullopt when the node has none or
    // that range is empty.
    std::optional<DrawItem> itemFor(const Scene& scene, const DrawItem& cg, const View& view) const;
    std::size_t size() const { return entries_.size(); }
    // Triangles in every entry's index lists, for the stats.
    std::size_t triangles() const;

private:
    static constexpr std::uint32_t kNone = ~0u;
    std::vector<std::uint32_t> slot_;  // per node id: index into entries_, or kNone
    std::vector<SilhouetteNode> entries_;
};

}  // namespace arcomp
