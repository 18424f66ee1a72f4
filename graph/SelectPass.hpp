#pragma once
// The select pass: one walk over the scene that culls against the view
// frustum and decides, per node, what to draw. Later node kinds add their
// decision (LOD level, grouping cut, silhouette region) to the same walk.
//
//   scene.update();
//   DrawList list;
//   select(scene, view, {.shading = Shading::Phong}, list);

#include "graph/DrawList.hpp"
#include "graph/SilhouetteNodes.hpp"
#include "graph/View.hpp"

#include <glm/glm.hpp>

namespace arcomp {

class LodTable;
struct GroupingNodes;

struct SelectSettings {
    Shading shading = Shading::Phong;
    // LOD nodes' settings and per-node state (graph/Lod.hpp); the pass
    // updates the state. Without it every LOD node shows its finest level.
    LodTable* lod = nullptr;
    // World-space gaze direction for the gaze policies; zero: the view's forward.
    glm::vec3 gaze{0.0f};
    // Frame time, for angular speeds and cross-fades.
    double timeSeconds = 0.0;
    // Silhouette nodes' region meshes (graph/SilhouetteNodes.hpp); without it
    // silhouette nodes draw nothing.
    const SilhouetteNodes* silhouettes = nullptr;
    // Grouping nodes' trees (graph/GroupingNodes.hpp); the pass writes the
    // proxies' matrices there. Without it every object is drawn.
    GroupingNodes* grouping = nullptr;
};

void select(const Scene& scene, const View& view, const SelectSettings& settings, DrawList& out);

} // namespace arcomp
