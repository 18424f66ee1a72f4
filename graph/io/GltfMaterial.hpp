#pragma once
// The material part of the glTF parser (graph/io/GltfParser.cpp): every
// material with its five texture slots (texCoord, KHR_texture_transform,
// sampler), emission and its strength, alpha mode and KHR_materials_unlit.
// Internal to graph/io: it sees tinygltf.

#include "graph/core/Material.hpp"

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace arcomp::gltf {

class GltfReader;

// The JSON names of Material::textures()'s slots, in its order, and how
// inspect and warnings call them.
constexpr std::array<const char*, 5> kSlotPointers{"pbrMetallicRoughness/baseColorTexture",
                                                   "pbrMetallicRoughness/metallicRoughnessTexture", "normalTexture",
                                                   "occlusionTexture", "emissiveTexture"};
constexpr std::array<const char*, 5> kSlotNames{"base colour", "metallic-roughness", "normal", "occlusion", "emissive"};

inline std::string materialLabel(std::size_t index, const std::string& name) {
    return "material " + std::to_string(index) + (name.empty() ? "" : " ('" + name + "')");
}

// The model's materials in its order. Every texture and sampler is checked,
// used or not, as meshes are; a texture mapped by a TEXCOORD_n above 1 is
// dropped with a warning. Throws ModelError naming a JSON pointer.
std::vector<Material> readMaterials(const tinygltf::Model& model, const std::vector<Image>& images,
                                    const GltfReader& reader, std::vector<std::string>& warnings);

}  // namespace arcomp::gltf
