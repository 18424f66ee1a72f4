#pragma once
// Cuts people out of the video where CG stands in front of them. Of the
// select pass's holdout bin, the items that reach nearer than the farthest
// person (along the view axis) are drawn with their silhouette meshes into
// the compositor's depth buffer; a person pixel behind that depth does not
// cover the CG. It reads the CG items after the budget controller, so each
// holdout is the silhouette of the level actually drawn.
//
//   HoldoutStage holdout;
//   holdout.cut(world, list, view, depths.farthest(), renderer, compositor, stats);   // after the CG draw

#include "graph/core/DrawList.hpp"
#include "graph/core/View.hpp"
#include "graph/core/World.hpp"
#include "runtime/composite/Compositor.hpp"
#include "runtime/render/Renderer.hpp"
#include "runtime/station/FrameStats.hpp"

namespace arcomp {

class HoldoutStage {
public:
    // Sets stats' objectsInFront (drawn: nearer than the farthest person
    // somewhere), objectsBehind (behind everyone) and holdoutTriangles.
    void cut(const World& world, const DrawList& cg, const View& view, float farthestPersonMetres, Renderer& renderer,
             Compositor& compositor, FrameStats& stats);
    // The last cut's holdout items, for drawing the mask again.
    const DrawList& drawn() const { return list_; }

private:
    DrawList list_;
};

}  // namespace arcomp
