#pragma once
// Cuts people out of the video where CG stands in front of them. Of the
// select pass's holdout bin, the items nearer than the person plane (along
// the view axis) are drawn with their silhouette meshes into the
// compositor's stencil, where the person layer will not cover the CG. It
// reads the CG items after the budget controller, so each holdout is the
// silhouette of the level actually drawn.
//
//   HoldoutStage holdout(cfg.compositing.compositor.personPlaneMetres);
//   holdout.cut(world, list, view, renderer, compositor, stats);   // after the CG draw

#include "graph/core/DrawList.hpp"
#include "graph/core/View.hpp"
#include "graph/core/World.hpp"
#include "runtime/Compositor.hpp"
#include "runtime/FrameStats.hpp"
#include "runtime/Renderer.hpp"

namespace arcomp {

class HoldoutStage {
public:
    explicit HoldoutStage(float personPlaneMetres) : personPlane_(personPlaneMetres) {}

    // Sets stats' objectsInFront, objectsBehind and holdoutTriangles.
    void cut(const World& world, const DrawList& cg, const View& view, Renderer& renderer, Compositor& compositor,
             FrameStats& stats);
    // The last cut's holdout items, for drawing the mask again.
    const DrawList& drawn() const { return list_; }

private:
    float personPlane_;
    DrawList list_;
};

} // namespace arcomp
