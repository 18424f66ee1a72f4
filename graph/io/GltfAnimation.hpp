#pragma once
// The animation and skin part of the glTF parser (graph/io/GltfParser.cpp),
// apart from meshes and materials. Internal to graph/io: it sees tinygltf.
//
// parseGltf() calls readGltfAnimation() once the node tree is parsed, with
// the accessor reader it checks mesh data with (GltfReader.hpp), so that
// animation data is held to the same bounds and type checks, and failures
// carry the same JSON pointers.

#include "graph/io/ModelLoader.hpp"

#include <optional>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
class Node;
}  // namespace tinygltf

namespace arcomp::gltf {
class GltfReader;
}

namespace arcomp {

// The pose a node's translation, rotation and scale give; none when the node
// gives a matrix. The node's fields must have been checked (nodeMatrix does).
std::optional<Trs> authoredTrs(const tinygltf::Node& node);

// Fills `out.animations` and `out.skins` and sets each parsed node's skin.
// `parsedOf[i]` is glTF node i's index in out.nodes, -1 when it is not in the
// drawn scene. Throws ModelError naming the file and a JSON pointer.
void readGltfAnimation(const tinygltf::Model& model, const gltf::GltfReader& reader, const std::vector<int>& parsedOf,
                       ParsedModel& out);

}  // namespace arcomp
