#pragma once
// Surface appearance: glTF 2.0's metallic-roughness material with the
// extensions a station draws (KHR_materials_unlit,
// KHR_materials_emissive_strength, KHR_texture_transform). The four shading
// levels use what they can afford of it: unlit draws base colour and
// emission, the top level all of it.

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace arcomp {

enum class AlphaMode : std::uint8_t { Opaque, Mask, Blend };

// glTF's sampler, with its GL enum values spelled out.
enum class TextureWrap : std::uint8_t { Repeat, ClampToEdge, MirroredRepeat };
enum class TextureFilter : std::uint8_t {
    Nearest,
    Linear,
    NearestMipmapNearest,
    LinearMipmapNearest,
    NearestMipmapLinear,
    LinearMipmapLinear,
};

struct Sampler {
    TextureFilter magFilter = TextureFilter::Linear;
    TextureFilter minFilter = TextureFilter::LinearMipmapLinear;
    TextureWrap wrapS = TextureWrap::Repeat;
    TextureWrap wrapT = TextureWrap::Repeat;
    bool operator==(const Sampler&) const = default;
};

// KHR_texture_transform: uv' = T(offset) * R(rotation) * S(scale) * uv.
struct TextureTransform {
    glm::vec2 offset{0.0f};
    float rotation = 0.0f;  // radians, counter-clockwise in uv space
    glm::vec2 scale{1.0f};
    bool operator==(const TextureTransform&) const = default;
    // The 3x3 matrix a shader multiplies (u, v, 1) by.
    glm::mat3 matrix() const;
};

// One texture slot of a material.
struct TextureRef {
    int image = -1;    // index into Scene images, -1 for none
    int texCoord = 0;  // 0: TEXCOORD_0, 1: TEXCOORD_1 (after the transform's override)
    Sampler sampler;
    TextureTransform transform;
    bool present() const { return image >= 0; }
};

struct Material {
    std::string name;
    glm::vec4 baseColor{0.8f, 0.8f, 0.8f, 1.0f};
    TextureRef baseColorTexture{};  // sRGB
    float metallic = 0.0f;
    float roughness = 1.0f;
    TextureRef metallicRoughnessTexture{};  // linear: roughness in G, metallic in B
    TextureRef normalTexture{};             // linear, tangent space
    float normalScale = 1.0f;
    TextureRef occlusionTexture{};  // linear, R
    float occlusionStrength = 1.0f;
    glm::vec3 emissive{0.0f};
    float emissiveStrength = 1.0f;  // KHR_materials_emissive_strength
    TextureRef emissiveTexture{};   // sRGB
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;
    bool unlit = false;  // KHR_materials_unlit: never shaded, whatever the level

    // Every texture slot, for code that treats them alike (rebasing image
    // indices, listing features).
    std::array<TextureRef*, 5> textures() {
        return {&baseColorTexture, &metallicRoughnessTexture, &normalTexture, &occlusionTexture, &emissiveTexture};
    }
    std::array<const TextureRef*, 5> textures() const {
        return {&baseColorTexture, &metallicRoughnessTexture, &normalTexture, &occlusionTexture, &emissiveTexture};
    }
};

// Eight-bit RGBA pixels, rows top to bottom; sRGB or linear is the user's
// business (a base colour texture is sRGB, a normal map linear).
struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
};

}  // namespace arcomp
