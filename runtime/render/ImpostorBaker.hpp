#pragma once
// Billboard impostors for grouping-tree groups (the better proxy the
// grouping paper names as its next step): each group's members are
// rendered once, at load time, orthographically around the group's sphere
// from the station camera's direction into an RGBA image that becomes an
// unlit, blended material; the select pass then draws the group as one
// quad facing the eye (graph/grouping/GroupingNodes.hpp). A GL context must be
// current.
//
//   bakeImpostors(scene, groupingNode, table, {.pixelsPerUnit = 0.5f});
//   table.nodes[scene.payload(groupingNode)].proxy = GroupingProxy::Impostor;
//
// Objects are drawn at their finest LOD level. Groups made later by a
// rebuild have no image and fall back to the box until baked again.

#include "graph/grouping/GroupingNodes.hpp"

#include <optional>

namespace arcomp {

struct ImpostorBakeSettings {
    float pixelsPerUnit = 0.5f;  // image pixels per scene unit of the group's size
    int minPixels = 8;
    int maxPixels = 256;
    // Each group is photographed from the direction of this point (the
    // station's camera) when given, else from +Z.
    std::optional<glm::vec3> eye;
};

// Bakes every group of the node's tree; returns how many.
std::size_t bakeImpostors(Scene& scene, NodeId groupingNode, GroupingNodes& table,
                          const ImpostorBakeSettings& settings);
// Bakes every grouping node of the scene whose proxy is Impostor, at its
// own pixels per unit, seen from `eye`.
std::size_t bakeImpostors(Scene& scene, GroupingNodes& table, const glm::vec3& eye);

}  // namespace arcomp
