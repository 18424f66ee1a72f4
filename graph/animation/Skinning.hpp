#pragma once
// Linear blend skinning on the CPU, the same sum the renderer's vertex
// shader takes: for culling bounds that cover every pose of an animation and
// for tests that check the GPU against hand-worked numbers.
//
//   scene.update();   // joint matrices follow the joints' world matrices
//   const glm::mat4 s = skinMatrix(g, v, scene.jointMatrices(part.skin));
//   const glm::vec3 posed = glm::vec3(s * glm::vec4(g.positions[v], 1.0f));   // in the mesh node's space
//
// After loading, fitPosedBounds() gives each skinned mesh node the bound of
// all its poses, so the select pass never culls a limb that an animation
// swings out of the bind pose's sphere.

#include "graph/animation/ModelAnimation.hpp"
#include "graph/core/Scene.hpp"

#include <span>
#include <vector>

namespace arcomp {

// glTF 2.0, 3.7.3.3 (skinned mesh attributes): the vertex's skin matrix is
// sum_i WEIGHTS_0[i] * jointMatrix[JOINTS_0[i]]. `g` must have joints and
// weights (Geometry::hasSkinInfluences) with joints inside the span.
glm::mat4 skinMatrix(const Geometry& g, std::size_t vertex, std::span<const glm::mat4> jointMatrices);

// Every position of `g` posed by the joint matrices, in the mesh's space.
std::vector<glm::vec3> skinPositions(const Geometry& g, std::span<const glm::mat4> jointMatrices);

// Sets the local bound of each mesh node in `meshes` whose part has a skin
// to the box over its poses: the scene as it stands, and each animation
// sampled at `samplesPerSecond` and at each of its key times. Plays the
// animations on `scene` to get there and puts the animated nodes back at
// their rest pose afterwards; ends with scene.update().
void fitPosedBounds(Scene& scene, std::span<const NodeId> meshes, std::span<const ModelAnimation> animations,
                    float samplesPerSecond = 30.0f);

}  // namespace arcomp
