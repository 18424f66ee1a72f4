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

} // namespace arcomp
