#include "graph/core/ObjectOpacity.hpp"

#include <algorithm>

namespace arcomp {
namespace {

// The product of the listed opacities on the way from `node` to the root.
float inheritedOpacity(const Scene& scene, const std::vector<ObjectOpacity>& table, NodeId node) {
    float opacity = 1.0f;
    for (; node != kNoNode && opacity > 0.0f; node = scene.parent(node)) opacity *= opacityOf(table, node);
    return opacity;
}

}  // namespace

void setOpacity(std::vector<ObjectOpacity>& table, NodeId node, float opacity) {
    opacity = std::clamp(opacity, 0.0f, 1.0f);
    const auto at = std::find_if(table.begin(), table.end(), [&](const ObjectOpacity& o) { return o.node == node; });
    if (opacity >= 1.0f) {
        if (at != table.end()) table.erase(at);
    } else if (at != table.end()) {
        at->opacity = opacity;
    } else {
        table.push_back({node, opacity});
    }
}

float opacityOf(const std::vector<ObjectOpacity>& table, NodeId node) {
    for (const ObjectOpacity& o : table)
        if (o.node == node) return o.opacity;
    return 1.0f;
}

void applyOpacity(const Scene& scene, const std::vector<ObjectOpacity>& table, DrawList& list) {
    if (table.empty()) return;
    // Items move down over the dropped ones; `moved` maps an old index to
    // its new one, so that each holdout still names its item.
    constexpr std::uint32_t kDropped = ~std::uint32_t{0};
    std::vector<std::uint32_t> moved(list.items.size(), kDropped);
    std::size_t kept = 0;
    for (std::size_t i = 0; i < list.items.size(); ++i) {
        const float opacity = inheritedOpacity(scene, table, list.items[i].node);
        if (opacity <= 0.0f) continue;
        list.items[kept] = list.items[i];
        list.items[kept].fade *= opacity;
        moved[i] = static_cast<std::uint32_t>(kept++);
    }
    list.items.resize(kept);
    std::erase_if(list.holdouts, [&](HoldoutItem& h) {
        h.cgItem = moved[h.cgItem];
        return h.cgItem == kDropped;
    });
    std::erase_if(list.pointClouds,
                  [&](const PointCloudItem& p) { return inheritedOpacity(scene, table, p.node) <= 0.0f; });
}

}  // namespace arcomp
