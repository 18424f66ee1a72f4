#pragma once
// A model's animation once its nodes are in a Scene: the clip, whose
// channels' `target` index `nodes`, and for each animated node its NodeId
// and the pose the file gave it. A channel replaces one of translation,
// rotation and scale; the other two stay at the rest pose.
//
//   LoadedModel m = loadModel("walker.gltf", scene, scene.root());
//   for (const ModelAnimation& a : m.animations) use(a.clip.name, a.clip.duration());

#include "graph/animation/AnimationClip.hpp"
#include "graph/core/Scene.hpp"

#include <string>
#include <vector>

namespace arcomp {

struct AnimatedNode {
    NodeId node = kNoNode;
    Trs rest;
};

struct ModelAnimation {
    AnimationClip clip;
    std::vector<AnimatedNode> nodes;
};

}  // namespace arcomp
