#pragma once
// Loading models into a scene: glTF 2.0 (.gltf, .glb) and Wavefront OBJ.
//
//   Scene scene;
//   LoadedModel m = loadModel("bunny.obj", scene, scene.root());
//   // m.root is a group named after the file; m.warnings lists what was
//   // skipped (points and lines, images that do not decode, textures on a
//   // TEXCOORD_n the primitive lacks, ...)
//   AnimationPlayer player(m.animations[0]);   // glTF animations, if any
//
// glTF normal maps on primitives without TANGENT get tangents generated
// (computeTangents, Geometry::tangentsGenerated).
//
// A model that would be unsafe to draw (indices or accessors out of range,
// wrong component types, cycles in the node graph, required extensions we do
// not support, URIs leaving the model's folder) throws ModelError and leaves
// the scene exactly as it was.

#include "graph/animation/ModelAnimation.hpp"
#include "graph/animation/Skin.hpp"
#include "graph/core/Scene.hpp"
#include "graph/io/ModelError.hpp"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace arcomp {

struct LoadedModel {
    NodeId root = kNoNode;
    std::vector<std::string> warnings;
    std::vector<std::string> notDrawn;  // extensions the file uses that arcomp leaves out
    // glTF animations, their channels bound to the placed nodes
    // (graph/animation/AnimationPlayer.hpp plays one).
    std::vector<ModelAnimation> animations;
    // glTF skins with joints and users as NodeIds, as the file has them; what
    // poses the meshes are the scene skins their parts name (Scene::addSkin).
    std::vector<Skin> skins;
};

// Each of the model's mesh parts becomes a Mesh node under its transform,
// unless `placeMesh` is given: then it is called instead (e.g. to put an LOD
// node with generated levels there).
using MeshPlacer = std::function<void(NodeId parent, MeshPart part)>;
LoadedModel loadModel(const std::filesystem::path& file, Scene& scene, NodeId parent, const MeshPlacer& placeMesh = {});

// A model parsed but not yet placed in a scene: nodes refer to each other by
// index into `nodes`, parents first.
struct ModelNode {
    int parent = -1;  // index into nodes, -1 for the model's root
    glm::mat4 local{1.0f};
    // The authored translation, rotation and scale that make `local`; an
    // animation channel replaces one of them. None for a node that gives a
    // matrix, which is why such a node may not be animated.
    std::optional<Trs> trs = Trs{};
    int skin = -1;                // index into the model's skins
    std::vector<MeshPart> parts;  // indices into the model's geometries and materials
    std::string name;
};

struct ParsedModel {
    std::vector<ModelNode> nodes;
    std::vector<Geometry> geometries;
    std::vector<Material> materials;
    std::vector<Image> images;
    std::vector<std::string> warnings;
    std::vector<std::string> notDrawn;      // extensions the file uses that arcomp leaves out
    std::vector<AnimationClip> animations;  // channel targets index `nodes`
    std::vector<Skin> skins;                // joints and users index `nodes`
};

// The two halves of loadModel, for a caller that looks at a model before
// placing it (a station config checks the animation it names).
ParsedModel parseModel(const std::filesystem::path& file);
LoadedModel placeModel(ParsedModel model, Scene& scene, NodeId parent, const std::string& name,
                       const MeshPlacer& placeMesh = {});

ParsedModel parseGltf(const std::filesystem::path& file);
ParsedModel parseObj(const std::filesystem::path& file);

}  // namespace arcomp
