#pragma once
// The select pass: one walk over the scene that culls against the view
// frustum and decides, per node, what to draw: LOD level, grouping cut,
// silhouette region. It sorts what it finds into the draw list's bins: CG
// items, holdouts (a CG mesh with an entry in world.holdouts), point clouds
// (graph/core/DrawList.hpp). Grouping proxies have no holdout: a group far
// enough to be drawn as its translucent proxy cuts no one out. Objects
// hidden or fading (world.opacity, graph/core/ObjectOpacity.hpp) are
// applied last.
//
//   world.scene.update();
//   DrawList list;
//   select(world, view, {.shading = Shading::Phong}, list);

#include "graph/core/DrawList.hpp"
#include "graph/core/View.hpp"
#include "graph/core/World.hpp"

#include <glm/glm.hpp>

namespace arcomp {

// This frame's inputs to select. The station leaves `lod` and `grouping`
// on; the papers' experiments and the benches turn them off to compare
// against full detail.
struct SelectSettings {
    Shading shading = Shading::Phong;
    // World-space gaze direction for the gaze policies; zero: the view's forward.
    glm::vec3 gaze{0.0f};
    // Frame time, for angular speeds and cross-fades.
    double timeSeconds = 0.0;
    // Off: every LOD node shows its finest level and keeps its history.
    bool lod = true;
    // Off: a grouping node's objects are all drawn, none as a proxy.
    bool grouping = true;
};

// Updates the LOD nodes' state and the grouping proxies' matrices in the
// world; reads the rest.
void select(World& world, const View& view, const SelectSettings& settings, DrawList& out);

}  // namespace arcomp
