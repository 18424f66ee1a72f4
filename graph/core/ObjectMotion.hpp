#pragma once
// A config mover: an object that goes back and forth along a straight line
// at constant speed, turning round `range` metres from where it was placed.
// Deterministic in time, so a replay moves it the same way every run.
//
//   ObjectMotion m{.node = place, .rest = local, .velocity = {0.5f, 0, 0}, .range = 3.0f};
//   scene.setLocal(m.node, glm::translate(glm::mat4(1), motionOffset(m, t)) * m.rest);

#include "graph/core/Scene.hpp"

namespace arcomp {

struct ObjectMotion {
    NodeId node = kNoNode;     // the object's placing transform
    glm::mat4 rest{1.0f};      // its local matrix at time 0
    glm::vec3 velocity{0.0f};  // scene units per second
    float range = 0.0f;        // 0: moves on for ever
    // When the object belongs to a grouping node: that node and the
    // object's index among its objects, so only its branch is rebuilt.
    NodeId groupingNode = kNoNode;
    std::uint32_t groupingObject = 0;
};

glm::vec3 motionOffset(const ObjectMotion& motion, double timeSeconds);
glm::vec3 motionVelocity(const ObjectMotion& motion, double timeSeconds);

}  // namespace arcomp
