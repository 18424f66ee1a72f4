#include "graph/io/GltfMaterial.hpp"

#include "graph/io/GltfReader.hpp"

namespace arcomp::gltf {
namespace {

// The GL enum values glTF's samplers hold.
constexpr int kGlNearest = 9728, kGlLinear = 9729, kGlNearestMipmapNearest = 9984, kGlLinearMipmapNearest = 9985,
              kGlNearestMipmapLinear = 9986, kGlLinearMipmapLinear = 9987;
constexpr int kGlClampToEdge = 33071, kGlMirroredRepeat = 33648, kGlRepeat = 10497;

// glTF leaves an absent filter to the implementation (tinygltf: -1), which
// takes Sampler's defaults. A value outside the spec's list fails, as the
// validator makes it an error (VALUE_NOT_IN_LIST): such a file was not
// written by a tool that knew what it meant.
Sampler toSampler(const tinygltf::Sampler& src, std::size_t index, const GltfReader& reader) {
    const std::string where = ptr("samplers", index);
    Sampler out;
    const auto filter = [&](int gl, const char* field, bool minification, TextureFilter& to) {
        switch (gl) {
        case -1: return;
        case kGlNearest: to = TextureFilter::Nearest; return;
        case kGlLinear: to = TextureFilter::Linear; return;
        default: break;
        }
        if (minification) {
            switch (gl) {
            case kGlNearestMipmapNearest: to = TextureFilter::NearestMipmapNearest; return;
            case kGlLinearMipmapNearest: to = TextureFilter::LinearMipmapNearest; return;
            case kGlNearestMipmapLinear: to = TextureFilter::NearestMipmapLinear; return;
            case kGlLinearMipmapLinear: to = TextureFilter::LinearMipmapLinear; return;
            default: break;
            }
        }
        reader.fail(where + "/" + field,
                    "is " + std::to_string(gl) + ", expected " +
                        (minification ? "9728, 9729 or 9984 to 9987 (NEAREST, LINEAR or a mipmap filter)"
                                      : "9728 (NEAREST) or 9729 (LINEAR)"));
    };
    const auto wrap = [&](int gl, const char* field) {
        switch (gl) {
        case -1:  // tinygltf's "unset", as for the filters: the default
        case kGlRepeat: return TextureWrap::Repeat;
        case kGlClampToEdge: return TextureWrap::ClampToEdge;
        case kGlMirroredRepeat: return TextureWrap::MirroredRepeat;
        default:
            reader.fail(where + "/" + field,
                        "is " + std::to_string(gl) +
                            ", expected 10497 (REPEAT), 33071 (CLAMP_TO_EDGE) or 33648 (MIRRORED_REPEAT)");
        }
    };
    filter(src.magFilter, "magFilter", false, out.magFilter);
    filter(src.minFilter, "minFilter", true, out.minFilter);
    out.wrapS = wrap(src.wrapS, "wrapS");
    out.wrapT = wrap(src.wrapT, "wrapT");
    return out;
}

float finiteNumber(const tinygltf::Value& v, const std::string& where, const GltfReader& reader) {
    if (!v.IsNumber() || !std::isfinite(v.GetNumberAsDouble())) reader.fail(where, "must be a finite number");
    return static_cast<float>(v.GetNumberAsDouble());
}

glm::vec2 finitePair(const tinygltf::Value& v, const std::string& where, const GltfReader& reader) {
    if (!v.IsArray() || v.ArrayLen() != 2) reader.fail(where, "must be an array of 2 numbers");
    return {finiteNumber(v.Get(0), where + "/0", reader), finiteNumber(v.Get(1), where + "/1", reader)};
}

int texCoordSet(const tinygltf::Value& v, const std::string& where, const GltfReader& reader) {
    const double d = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
    if (!(d >= 0.0 && d <= 1e6 && d == std::floor(d)))
        reader.fail(where, "must be an integer of 0 or more (the n of TEXCOORD_n)");
    return static_cast<int>(d);
}

// KHR_texture_transform on one textureInfo; its texCoord replaces the
// textureInfo's own.
TextureTransform readTransform(const tinygltf::Value& ext, const std::string& where, int& texCoord,
                               const GltfReader& reader) {
    if (!ext.IsObject()) reader.fail(where, "must be an object");
    TextureTransform t;
    if (ext.Has("offset")) t.offset = finitePair(ext.Get("offset"), where + "/offset", reader);
    if (ext.Has("rotation")) t.rotation = finiteNumber(ext.Get("rotation"), where + "/rotation", reader);
    if (ext.Has("scale")) t.scale = finitePair(ext.Get("scale"), where + "/scale", reader);
    if (ext.Has("texCoord")) texCoord = texCoordSet(ext.Get("texCoord"), where + "/texCoord", reader);
    return t;
}

// What every material's textures need, checked once: each texture's image
// and sampler exist, and the samplers in arcomp's terms.
struct TextureTables {
    const tinygltf::Model& model;
    const std::vector<Image>& images;
    std::vector<Sampler> samplers;
};

TextureTables textureTables(const tinygltf::Model& model, const std::vector<Image>& images, const GltfReader& reader) {
    TextureTables tables{model, images, {}};
    for (std::size_t i = 0; i < model.samplers.size(); ++i)
        tables.samplers.push_back(toSampler(model.samplers[i], i, reader));
    for (std::size_t i = 0; i < model.textures.size(); ++i) {
        const tinygltf::Texture& t = model.textures[i];
        if (t.source < -1 || t.source >= static_cast<int>(images.size()))
            reader.fail(ptr("textures", i, "source"), "image " + std::to_string(t.source) + " does not exist (" +
                                                          std::to_string(images.size()) + " images)");
        if (t.sampler < -1 || t.sampler >= static_cast<int>(tables.samplers.size()))
            reader.fail(ptr("textures", i, "sampler"), "sampler " + std::to_string(t.sampler) + " does not exist (" +
                                                           std::to_string(tables.samplers.size()) + " samplers)");
    }
    return tables;
}

// Any slot's textureInfo (tinygltf has a type for plain, normal and
// occlusion ones). `where` points at the textureInfo. An image that did not
// decode leaves the slot empty; its warning was given when it failed.
template <class Info>
TextureRef readTexture(const Info& info, const std::string& where, const TextureTables& tables,
                       const GltfReader& reader) {
    TextureRef ref;
    if (info.index == -1) return ref;  // tinygltf's "no such textureInfo"
    if (info.index < 0 || static_cast<std::size_t>(info.index) >= tables.model.textures.size())
        reader.fail(where + "/index", "texture " + std::to_string(info.index) + " does not exist (" +
                                          std::to_string(tables.model.textures.size()) + " textures)");
    if (info.texCoord < 0)
        reader.fail(where + "/texCoord",
                    "is " + std::to_string(info.texCoord) + ", expected 0 or more (the n of TEXCOORD_n)");
    ref.texCoord = info.texCoord;
    if (const auto e = info.extensions.find("KHR_texture_transform"); e != info.extensions.end())
        ref.transform = readTransform(e->second, where + "/extensions/KHR_texture_transform", ref.texCoord, reader);
    const tinygltf::Texture& texture = tables.model.textures[static_cast<std::size_t>(info.index)];
    if (texture.sampler >= 0) ref.sampler = tables.samplers[static_cast<std::size_t>(texture.sampler)];
    if (texture.source >= 0 && !tables.images[static_cast<std::size_t>(texture.source)].rgba.empty())
        ref.image = texture.source;
    return ref;
}

Material readMaterial(const tinygltf::Material& src, std::size_t index, const TextureTables& tables,
                      const GltfReader& reader, std::vector<std::string>& warnings) {
    const std::string where = ptr("materials", index);
    Material m;
    m.name = src.name;
    const auto& pbr = src.pbrMetallicRoughness;
    if (pbr.baseColorFactor.size() == 4)
        m.baseColor =
            glm::vec4(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2], pbr.baseColorFactor[3]);
    m.metallic = static_cast<float>(pbr.metallicFactor);
    m.roughness = static_cast<float>(pbr.roughnessFactor);
    m.baseColorTexture = readTexture(pbr.baseColorTexture, where + "/" + kSlotPointers[0], tables, reader);
    m.metallicRoughnessTexture =
        readTexture(pbr.metallicRoughnessTexture, where + "/" + kSlotPointers[1], tables, reader);
    m.normalTexture = readTexture(src.normalTexture, where + "/" + kSlotPointers[2], tables, reader);
    m.normalScale = static_cast<float>(src.normalTexture.scale);
    m.occlusionTexture = readTexture(src.occlusionTexture, where + "/" + kSlotPointers[3], tables, reader);
    m.occlusionStrength = static_cast<float>(src.occlusionTexture.strength);
    m.emissiveTexture = readTexture(src.emissiveTexture, where + "/" + kSlotPointers[4], tables, reader);
    if (src.emissiveFactor.size() == 3)
        m.emissive = glm::vec3(src.emissiveFactor[0], src.emissiveFactor[1], src.emissiveFactor[2]);
    if (const auto e = src.extensions.find("KHR_materials_emissive_strength"); e != src.extensions.end()) {
        const std::string at = where + "/extensions/KHR_materials_emissive_strength";
        if (!e->second.IsObject()) reader.fail(at, "must be an object");
        if (e->second.Has("emissiveStrength")) {
            m.emissiveStrength = finiteNumber(e->second.Get("emissiveStrength"), at + "/emissiveStrength", reader);
            if (m.emissiveStrength < 0.0f) reader.fail(at + "/emissiveStrength", "is negative, expected 0 or more");
        }
    }
    m.alphaMode = src.alphaMode == "BLEND"  ? AlphaMode::Blend
                  : src.alphaMode == "MASK" ? AlphaMode::Mask
                                            : AlphaMode::Opaque;
    m.alphaCutoff = static_cast<float>(src.alphaCutoff);
    m.doubleSided = src.doubleSided;
    m.unlit = src.extensions.count("KHR_materials_unlit") > 0;

    // Geometry carries TEXCOORD_0 and TEXCOORD_1 only; a texture mapped by
    // another set is drawn as if absent rather than with the wrong uvs.
    const auto slots = m.textures();
    for (std::size_t k = 0; k < slots.size(); ++k) {
        if (slots[k]->texCoord <= 1) continue;
        if (slots[k]->present())
            warnings.push_back(where + "/" + kSlotPointers[k] + ": reads TEXCOORD_" +
                               std::to_string(slots[k]->texCoord) + ", arcomp reads TEXCOORD_0 and TEXCOORD_1 only; " +
                               materialLabel(index, m.name) + " drawn without its " + kSlotNames[k] + " texture");
        *slots[k] = TextureRef{};
    }
    return m;
}

}  // namespace

std::vector<Material> readMaterials(const tinygltf::Model& model, const std::vector<Image>& images,
                                    const GltfReader& reader, std::vector<std::string>& warnings) {
    const TextureTables textures = textureTables(model, images, reader);
    std::vector<Material> out;
    for (std::size_t i = 0; i < model.materials.size(); ++i)
        out.push_back(readMaterial(model.materials[i], i, textures, reader, warnings));
    return out;
}

}  // namespace arcomp::gltf
