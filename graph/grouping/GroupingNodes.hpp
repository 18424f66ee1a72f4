#pragma once
// The side table behind NodeKind::Grouping nodes. A grouping node's
// children are its objects (each a whole subtree: transforms, LOD nodes,
// meshes); the grouping tree over them lives here, not in the scene, so that
// regrouping never touches the scene's structure. The select pass walks the
// tree (the paper's NodeChoice): a group whose Ω at the current eye
// distance is below Ωt is drawn as its proxy, otherwise its children are
// tried; an object reached on its own is visited as a normal subtree, so
// its LOD node picks its level.
//
//   NodeId g = addGroupingNode(world.scene, world.scene.root(), world.grouping);
//   ... add each object's subtree under g ...
//   world.scene.update();
//   buildGrouping(world.scene, g, world.grouping, params);   // at load time
//   select(world, view, {}, list);                           // graph/core/World.hpp
//
// Proxies (selectable per node): the paper's box in the group's mean colour,
// alpha-blended, or a camera-facing billboard with an image of the members
// baked at load time (runtime/render/ImpostorBaker.hpp); a group with no baked
// image falls back to the box.

#include "graph/core/Scene.hpp"
#include "graph/grouping/GroupingTree.hpp"

#include <span>
#include <string>
#include <vector>

namespace arcomp {

enum class GroupingProxy : std::uint8_t { Box, Impostor };

struct GroupingNode {
    GroupingTree tree;
    std::vector<NodeId> objects;  // object i's subtree root: the node's i-th child
    float omegaT = 0.011f;        // the threshold the per-frame choice uses
    GroupingProxy proxy = GroupingProxy::Box;
    float proxyAlpha = 0.7f;
    float impostorPixelsPerUnit = 0.5f;  // for bakers: image pixels per scene unit
    MeshPart boxPart{};                  // a unit box with a white blended material; tinted per group
    std::uint32_t quadGeometry = 0;      // a unit quad in XY facing +Z, for impostors
    // Per tree node: the baked impostor's material, or kNoImpostor, and the
    // sphere it was baked around. A group that moved or was remade since
    // (its slot reused) no longer matches that sphere and shows its box.
    static constexpr std::uint32_t kNoImpostor = ~std::uint32_t{0};
    std::vector<std::uint32_t> impostorMaterial;
    std::vector<Sphere> impostorBound;
    bool impostorFits(std::uint32_t t) const;

    // Per tree node, written by the select pass: the proxy's model matrix
    // (draw items point at it until the next select).
    std::vector<glm::mat4> proxyModel;
    // Slot of object i in scene.siblingLayout(); refreshed by the
    // select pass when the scene's order changed.
    std::vector<std::uint32_t> objectSlot;
    // The select pass's work list: tree nodes to choose, and whether inside the frustum.
    std::vector<std::pair<std::uint32_t, bool>> pending;
};

struct GroupingNodes {
    std::vector<GroupingNode> nodes;
};

NodeId addGroupingNode(Scene& scene, NodeId parent, GroupingNodes& table, std::string name = {});

// The object a subtree is, for the measure: the box of its meshes in world
// space and their base colour, averaged by surface area.
GroupingItem groupingItemOf(const Scene& scene, NodeId subtree);

// Builds the grouping tree over the grouping node's children (call after
// scene.update()); sets the node's Ωt to params.omegaT.
void buildGrouping(Scene& scene, NodeId groupingNode, GroupingNodes& table, const GroupingParams& params);

// After objects of a grouping node moved (their transforms set and
// scene.update() run): takes their new boxes and velocities (scene units
// per second) into the tree and rebuilds only the branches they are in.
//
//   scene.setLocal(f.trees[3], m); scene.update();
//   regroupMoved(scene, f.grouping, table, {{3, velocity}});
struct MovedObject {
    std::uint32_t object;
    glm::vec3 velocity{0.0f};
};
GroupingRebuildStats regroupMoved(const Scene& scene, NodeId groupingNode, GroupingNodes& table,
                                  std::span<const MovedObject> moved);

// A proxy's model matrix: the unit box scaled to the group's box, or the
// unit quad facing the eye, spanning the diameter of the group's sphere
// (its image was baked orthographically around that sphere).
glm::mat4 boxProxyModel(const Box& box);
glm::mat4 billboardModel(const Sphere& bound, const glm::vec3& eye);
// The quad's frame for an eye direction: +Z towards the eye, +Y as near
// world up as it can be; bakers render with the same frame.
glm::mat3 billboardFrame(const glm::vec3& towardsEye);

}  // namespace arcomp
