#pragma once
// Billboard impostors for grouping-tree groups (the better proxy the
// grouping paper names as its next step): each group's members are
// rendered once, at load time, orthographically from +Z into an RGBA image
// that becomes an unlit, blended material; the select pass then draws the
// group as one quad turned towards the eye (graph/GroupingNodes.hpp). A GL
// context must be current.
//
//   bakeImpostors(scene, groupingNode, table, {.pixelsPerUnit = 0.5f});
//   table.nodes[scene.payload(groupingNode)].proxy = GroupingProxy::Impostor;
//
// Objects are drawn at their finest LOD level. Groups made later by a
// rebuild have no image and fall back to the box until baked again.

#include "graph/GroupingNodes.hpp"

namespace arcomp {

struct ImpostorBakeSettings {
    float pixelsPerUnit = 0.5f;  // image pixels per scene unit of the group's size
    int minPixels = 8;
    int maxPixels = 256;
};

// Bakes every group of the node's tree; returns how many.
std::size_t bakeImpostors(Scene& scene, NodeId groupingNode, GroupingNodes& table, const ImpostorBakeSettings& settings);
// Bakes every grouping node of the scene whose proxy is Impostor, at its
// own pixels per unit.
std::size_t bakeImpostors(Scene& scene, GroupingNodes& table);

} // namespace arcomp
