#pragma once
// The select pass: one walk over the scene that culls against the view
// frustum and decides, per node, what to draw: LOD level, grouping cut,
// silhouette region. It sorts what it finds into the draw list's bins: CG
// items, holdouts, point clouds (graph/core/DrawList.hpp).
//
//   scene.update();
//   DrawList list;
//   select(scene, view, {.shading = Shading::Phong}, list);

#include "graph/core/DrawList.hpp"
#include "graph/silhouette/HoldoutMeshes.hpp"
#include "graph/silhouette/SilhouetteNodes.hpp"
#include "graph/core/View.hpp"

#include <glm/glm.hpp>

namespace arcomp {

class LodTable;
struct GroupingNodes;

struct SelectSettings {
    Shading shading = Shading::Phong;
    // LOD nodes' settings and per-node state (graph/lod/Lod.hpp); the pass
    // updates the state. Without it every LOD node shows its finest level.
    LodTable* lod = nullptr;
    // World-space gaze direction for the gaze policies; zero: the view's forward.
    glm::vec3 gaze{0.0f};
    // Frame time, for angular speeds and cross-fades.
    double timeSeconds = 0.0;
    // Silhouette nodes' region meshes (graph/silhouette/SilhouetteNodes.hpp); without it
    // silhouette nodes draw nothing.
    const SilhouetteNodes* silhouettes = nullptr;
    // Grouping nodes' trees (graph/grouping/GroupingNodes.hpp); the pass writes the
    // proxies' matrices there. Without it every object is drawn.
    GroupingNodes* grouping = nullptr;
    // Holdout meshes of the CG meshes; a mesh item with one is also put in
    // the holdout bin. Grouping proxies have none: a group far enough to be
    // drawn as its translucent proxy cuts no one out.
    const HoldoutMeshes* holdouts = nullptr;
};

void select(const Scene& scene, const View& view, const SelectSettings& settings, DrawList& out);

} // namespace arcomp
