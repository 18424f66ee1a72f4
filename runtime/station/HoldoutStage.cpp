#include "runtime/station/HoldoutStage.hpp"

namespace arcomp {

void HoldoutStage::cut(const World& world, const DrawList& cg, const View& view, float farthestPersonMetres,
                       Renderer& renderer, Compositor& compositor, FrameStats& stats) {
    list_.clear();
    stats.objectsInFront = stats.objectsBehind = 0;
    for (const HoldoutItem& h : cg.holdouts) {
        const DrawItem& item = cg.items[h.cgItem];
        if (h.depth - world.scene.worldBound(item.node).radius >= farthestPersonMetres) {
            ++stats.objectsBehind;
            continue;
        }
        ++stats.objectsInFront;
        if (const std::optional<DrawItem> holdout = world.holdouts.itemFor(world.scene, item, view))
            list_.items.push_back(*holdout);
    }
    compositor.beginHoldout();
    renderer.draw(world.scene, list_, view, {.clearColor = std::nullopt, .coverageOnly = true});
    compositor.endHoldout();
    stats.holdoutTriangles = renderer.trianglesDrawn();
}

}  // namespace arcomp
