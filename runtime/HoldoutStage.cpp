#include "runtime/HoldoutStage.hpp"

namespace arcomp {

void HoldoutStage::cut(const World& world, const DrawList& cg, const View& view, Renderer& renderer,
                       Compositor& compositor, FrameStats& stats) {
    // One plane stands for every person for now: an object's centre nearer
    // than it is in front of them all.
    list_.clear();
    stats.objectsInFront = stats.objectsBehind = 0;
    for (const HoldoutItem& h : cg.holdouts) {
        if (h.depth >= personPlane_) {
            ++stats.objectsBehind;
            continue;
        }
        ++stats.objectsInFront;
        if (const std::optional<DrawItem> item = world.holdouts.itemFor(world.scene, cg.items[h.cgItem], view))
            list_.items.push_back(*item);
    }
    compositor.beginHoldout();
    renderer.draw(world.scene, list_, view, {.clearColor = std::nullopt});
    compositor.endHoldout();
    stats.holdoutTriangles = renderer.trianglesDrawn();
}

} // namespace arcomp
