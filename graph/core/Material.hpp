#pragma once
// Surface appearance: glTF 2.0's metallic-roughness material, reduced to
// what the four shading levels (unlit, flat, Gouraud, Phong) use.

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace arcomp {

enum class AlphaMode : std::uint8_t { Opaque, Mask, Blend };

struct Material {
    std::string name;
    glm::vec4 baseColor{0.8f, 0.8f, 0.8f, 1.0f};
    int baseColorImage = -1;  // index into Scene images, -1 for none
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    float metallic = 0.0f;
    float roughness = 1.0f;
    bool doubleSided = false;
    bool unlit = false;  // KHR_materials_unlit: never shaded, whatever the level
};

// Eight-bit sRGB RGBA pixels, rows top to bottom.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
};

} // namespace arcomp
