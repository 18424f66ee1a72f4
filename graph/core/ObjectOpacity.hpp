#pragma once
// How much of an object is drawn: hidden (0), fading (between) or shown
// (1), set on the object's node and carried to everything under it. The
// select pass applies it last (graph/core/SelectPass.hpp), so the renderer,
// the shadows, the holdouts and the budget all see the same list: a hidden
// object is not drawn, casts no shadow and cuts no one out of the video; a
// fading one is drawn blended, and still cuts. Only objects that are not
// fully shown are listed, so a scene without hidden objects pays nothing.
//
//   setOpacity(world.opacity, sign, 0.0f);           // hidden
//   setOpacity(world.opacity, sign, 0.5f);           // half faded in
//   select(world, view, settings, list);             // no item of the sign's, or each at half

#include "graph/core/DrawList.hpp"
#include "graph/core/Scene.hpp"

#include <vector>

namespace arcomp {

struct ObjectOpacity {
    NodeId node = kNoNode;
    float opacity = 1.0f;  // 0 hidden .. 1 shown
};

// Sets `node`'s opacity (clamped to 0..1); 1 takes it off the list.
void setOpacity(std::vector<ObjectOpacity>& table, NodeId node, float opacity);
// 1 for a node not on the list.
float opacityOf(const std::vector<ObjectOpacity>& table, NodeId node);
// Multiplies each item's fade by the opacities of its node and the node's
// ancestors, and drops the items (with their holdouts) and point clouds
// that come to 0.
void applyOpacity(const Scene& scene, const std::vector<ObjectOpacity>& table, DrawList& list);

}  // namespace arcomp
