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

namespace arcomp {

struct SelectSettings {
    Shading shading = Shading::Phong;
    const SilhouetteNodes* silhouettes = nullptr;  // required when the scene has SilhouetteRegion nodes
};

void select(const Scene& scene, const View& view, const SelectSettings& settings, DrawList& out);

} // namespace arcomp
