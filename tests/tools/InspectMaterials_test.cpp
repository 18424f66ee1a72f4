// `arcomp inspect` lists, for each material a mesh draws with, the glTF
// features it uses, one line per material in a fixed order.

#include "../support/QuadGltf.hpp"
#include "../support/Shell.hpp"
#include "../support/TempDir.hpp"

#include <gtest/gtest.h>

using arcomp::test::arcompCommand;
using arcomp::test::QuadGltf;
using arcomp::test::ShellResult;
using arcomp::test::TempDir;

namespace {

std::string lineStarting(const std::string& text, const std::string& start) {
    const std::size_t at = text.find("\n" + start);
    if (at == std::string::npos) return "(no line starting \"" + start + "\")";
    const std::size_t end = text.find('\n', at + 1);
    return text.substr(at + 1, end == std::string::npos ? std::string::npos : end - at - 1);
}

}  // namespace

TEST(InspectMaterials, eachDrawnMaterialListsItsFeatures) {
    QuadGltf q;
    q.extensionsUsed = R"(["KHR_texture_transform", "KHR_materials_emissive_strength", "KHR_materials_unlit"])";
    q.primitives = R"([
        {"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2, "TEXCOORD_1": 3}, "indices": 9, "material": 0},
        {"attributes": {"POSITION": 0, "TEXCOORD_0": 2, "COLOR_0": 4}, "indices": 9, "material": 1},
        {"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2, "TANGENT": 7}, "indices": 9, "material": 2}])";
    q.materials = R"([
        {"name": "brick",
         "pbrMetallicRoughness": {"metallicFactor": 0, "roughnessFactor": 0.5, "baseColorTexture": {"index": 0},
                                  "metallicRoughnessTexture": {"index": 0, "texCoord": 1}},
         "normalTexture": {"index": 0}, "occlusionTexture": {"index": 0, "strength": 0.5},
         "emissiveFactor": [0.2, 0.8, 1.0],
         "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 5}},
         "alphaMode": "MASK", "doubleSided": true},
        {"name": "glow", "extensions": {"KHR_materials_unlit": {}}, "alphaMode": "BLEND",
         "pbrMetallicRoughness": {"baseColorTexture": {"index": 0,
             "extensions": {"KHR_texture_transform": {"scale": [2, 2]}}}}},
        {"name": "tiles", "normalTexture": {"index": 0, "scale": 0.75}},
        {"name": "spare"}])";
    TempDir dir;
    const ShellResult r = arcompCommand("inspect " + dir.write("quad.gltf", q.json()).string());
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(lineStarting(r.out, "material 0 "),
              "material 0 'brick': metallic-roughness (m 0.0, r 0.5), base colour texture, metallic-roughness texture, "
              "normal map (scale 1), occlusion (strength 0.5), emissive (0.2 0.8 1.0 x5), alpha MASK 0.5, "
              "double-sided, TEXCOORD_1, tangents generated")
        << r.out;
    EXPECT_EQ(lineStarting(r.out, "material 1 "),
              "material 1 'glow': unlit, base colour texture, alpha BLEND, texture transform, vertex colours")
        << r.out;
    EXPECT_EQ(lineStarting(r.out, "material 2 "), "material 2 'tiles': metallic-roughness (m 1.0, r 1.0), "
                                                  "normal map (scale 0.75), tangents")
        << r.out;
    EXPECT_EQ(r.out.find("'spare'"), std::string::npos) << "a material no mesh draws with is not listed\n" << r.out;
    EXPECT_EQ(r.out.find("'default'"), std::string::npos) << r.out;
}

TEST(InspectMaterials, extensionsTheFileUsesAndArcompLeavesOutAreListedAsNotDrawn) {
    QuadGltf q;
    q.extensionsUsed = R"(["KHR_materials_unlit", "KHR_lights_punctual", "KHR_materials_clearcoat"])";
    TempDir dir;
    const ShellResult r = arcompCommand("inspect " + dir.write("quad.gltf", q.json()).string());
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(lineStarting(r.out, "not drawn:"), "not drawn: KHR_lights_punctual KHR_materials_clearcoat") << r.out;
}
