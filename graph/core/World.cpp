#include "graph/core/World.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <map>

namespace arcomp {

void moveObjects(World& world, double seconds) {
    if (world.motions.empty()) return;
    for (const ObjectMotion& m : world.motions)
        world.scene.setLocal(m.node, glm::translate(glm::mat4(1.0f), motionOffset(m, seconds)) * m.rest);
    world.scene.update();
    std::map<NodeId, std::vector<MovedObject>> moved;
    for (const ObjectMotion& m : world.motions)
        if (m.groupingNode != kNoNode) moved[m.groupingNode].push_back({m.groupingObject, motionVelocity(m, seconds)});
    for (const auto& [node, objects] : moved) regroupMoved(world.scene, node, world.grouping, objects);
}

void animateObjects(World& world, double seconds) {
    if (world.animations.empty()) return;
    for (ObjectAnimation& a : world.animations) a.player.apply(world.scene, seconds);
    world.scene.update();
    // An animation changes the object's shape, not its place: no velocity
    // for the grouping measure, but its bound and box are new.
    std::map<NodeId, std::vector<MovedObject>> changed;
    for (const ObjectAnimation& a : world.animations)
        if (a.groupingNode != kNoNode) changed[a.groupingNode].push_back({a.groupingObject, glm::vec3(0.0f)});
    for (const auto& [node, objects] : changed) regroupMoved(world.scene, node, world.grouping, objects);
}

std::pair<NodeId, std::uint32_t> groupingSlot(const World& world, NodeId node) {
    const NodeId parent = world.scene.parent(node);
    if (parent == kNoNode || world.scene.kind(parent) != NodeKind::Grouping) return {kNoNode, 0};
    const std::vector<NodeId>& objects = world.grouping.nodes[world.scene.payload(parent)].objects;
    const auto it = std::find(objects.begin(), objects.end(), node);
    if (it == objects.end()) return {kNoNode, 0};
    return {parent, static_cast<std::uint32_t>(it - objects.begin())};
}

const NamedObject* findObject(const World& world, const std::string& name) {
    for (const NamedObject& o : world.objects)
        if (o.name == name) return &o;
    return nullptr;
}

bool movesOverTime(const World& world, NodeId n) {
    for (; n != kNoNode; n = world.scene.parent(n)) {
        for (const ObjectMotion& m : world.motions)
            if (m.node == n) return true;
        for (const ObjectAnimation& a : world.animations)
            if (a.node == n) return true;
    }
    return false;
}

}  // namespace arcomp
