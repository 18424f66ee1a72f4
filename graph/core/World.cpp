#include "graph/core/World.hpp"

#include <glm/gtc/matrix_transform.hpp>

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
