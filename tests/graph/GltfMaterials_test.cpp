// glTF materials and the vertex attributes they draw with: every textureInfo
// field, samplers, KHR_texture_transform, KHR_materials_emissive_strength,
// TEXCOORD_1, TANGENT, COLOR_0, and the tangents generated for normal maps.

#include "graph/io/ModelLoader.hpp"

#include "../support/QuadGltf.hpp"
#include "../support/TempDir.hpp"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>

using namespace arcomp;
using arcomp::test::QuadGltf;
using arcomp::test::TempDir;

namespace {

struct Loaded {
    Scene scene;
    LoadedModel model;
    const Geometry& geometry(std::size_t i = 0) const { return scene.geometry(static_cast<std::uint32_t>(i)); }
    // The material the i-th mesh node draws with.
    const Material& materialOfMesh(std::size_t i = 0) const {
        std::size_t seen = 0;
        for (NodeId n : scene.order())
            if (scene.kind(n) == NodeKind::Mesh && seen++ == i) return scene.material(scene.meshPart(n).material);
        throw std::runtime_error("no such mesh");
    }
    bool warned(const std::string& part) const {
        return std::any_of(model.warnings.begin(), model.warnings.end(),
                           [&](const std::string& w) { return w.find(part) != std::string::npos; });
    }
};

std::unique_ptr<Loaded> load(const QuadGltf& q) {
    TempDir dir;
    auto out = std::make_unique<Loaded>();
    out->model = loadModel(dir.write("quad.gltf", q.json()), out->scene, out->scene.root());
    out->scene.update();  // order() lists the nodes after an update
    return out;
}

void expectMaterialRejected(const QuadGltf& q, const std::string& where, const std::string& reasonPart) {
    TempDir dir;
    const auto file = dir.write("bad.gltf", q.json());
    Scene scene;
    try {
        loadModel(file, scene, scene.root());
        ADD_FAILURE() << "loaded, expected a refusal at " << where;
    } catch (const ModelError& e) {
        EXPECT_EQ(e.where, where) << e.what();
        EXPECT_NE(e.reason.find(reasonPart), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("bad.gltf"), std::string::npos) << e.what();
    }
}

void expectTangent(const glm::vec4& t, const glm::vec4& want) {
    EXPECT_NEAR(t.x, want.x, 1e-5f);
    EXPECT_NEAR(t.y, want.y, 1e-5f);
    EXPECT_NEAR(t.z, want.z, 1e-5f);
    EXPECT_EQ(t.w, want.w);
}

const char* kWithUv1 =
    R"([{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2, "TEXCOORD_1": 3}, "indices": 9, "material": 0}])";

}  // namespace

TEST(GltfMaterials, everySlotFactorAndExtensionIsRead) {
    QuadGltf q;
    q.primitives = kWithUv1;
    q.extensionsUsed = R"(["KHR_texture_transform", "KHR_materials_emissive_strength"])";
    q.extensionsRequired = q.extensionsUsed;
    q.samplers = R"([{"magFilter": 9728, "minFilter": 9986, "wrapS": 33071, "wrapT": 33648},
                     {"magFilter": -1, "minFilter": -1, "wrapS": -1}])";
    q.textures = R"([{"source": 0, "sampler": 0}, {"source": 0, "sampler": 1}, {"source": 0}])";
    q.materials = R"([{"name": "all",
        "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.25, 1, 0.75], "metallicFactor": 0.1, "roughnessFactor": 0.6,
            "baseColorTexture": {"index": 0, "texCoord": 1},
            "metallicRoughnessTexture": {"index": 1}},
        "normalTexture": {"index": 2, "scale": 0.5},
        "occlusionTexture": {"index": 0, "strength": 0.25},
        "emissiveTexture": {"index": 1, "extensions": {"KHR_texture_transform":
            {"offset": [0.5, 0.25], "rotation": 1.5, "scale": [2, 3], "texCoord": 1}}},
        "emissiveFactor": [0.2, 0.8, 1.0],
        "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 5}},
        "alphaMode": "MASK", "alphaCutoff": 0.3, "doubleSided": true}])";
    const auto l = load(q);
    const Material& m = l->materialOfMesh();
    EXPECT_EQ(m.name, "all");
    EXPECT_EQ(m.baseColor, glm::vec4(0.5f, 0.25f, 1.0f, 0.75f));
    EXPECT_FLOAT_EQ(m.metallic, 0.1f);
    EXPECT_FLOAT_EQ(m.roughness, 0.6f);
    for (const TextureRef* t : m.textures()) EXPECT_EQ(t->image, 0);
    EXPECT_EQ(m.baseColorTexture.texCoord, 1);
    const Sampler custom{.magFilter = TextureFilter::Nearest,
                         .minFilter = TextureFilter::NearestMipmapLinear,
                         .wrapS = TextureWrap::ClampToEdge,
                         .wrapT = TextureWrap::MirroredRepeat};
    EXPECT_EQ(m.baseColorTexture.sampler, custom);
    EXPECT_EQ(m.occlusionTexture.sampler, custom);
    EXPECT_EQ(m.metallicRoughnessTexture.sampler, Sampler{});  // -1 or absent: the defaults
    EXPECT_EQ(m.normalTexture.sampler, Sampler{});             // a texture with no sampler
    EXPECT_EQ(m.metallicRoughnessTexture.texCoord, 0);
    EXPECT_FLOAT_EQ(m.normalScale, 0.5f);
    EXPECT_FLOAT_EQ(m.occlusionStrength, 0.25f);
    EXPECT_EQ(m.emissive, glm::vec3(0.2f, 0.8f, 1.0f));
    EXPECT_FLOAT_EQ(m.emissiveStrength, 5.0f);
    EXPECT_EQ(m.emissiveTexture.texCoord, 1);  // the transform's override
    EXPECT_EQ(m.emissiveTexture.transform, (TextureTransform{{0.5f, 0.25f}, 1.5f, {2.0f, 3.0f}}));
    EXPECT_EQ(m.baseColorTexture.transform, TextureTransform{});
    EXPECT_EQ(m.alphaMode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(m.alphaCutoff, 0.3f);
    EXPECT_TRUE(m.doubleSided);
    EXPECT_FALSE(m.unlit);
    EXPECT_TRUE(l->model.warnings.empty()) << l->model.warnings.front();
}

TEST(GltfMaterials, texturesOfASecondModelPointAtItsOwnImages) {
    QuadGltf q;
    q.materials = R"([{"occlusionTexture": {"index": 0}, "emissiveTexture": {"index": 0}}])";
    TempDir dir;
    const auto file = dir.write("quad.gltf", q.json());
    Scene scene;
    loadModel(file, scene, scene.root());
    loadModel(file, scene, scene.root());
    scene.update();
    ASSERT_EQ(scene.images().size(), 2u);
    std::vector<int> images;
    for (NodeId n : scene.order())
        if (scene.kind(n) == NodeKind::Mesh)
            images.push_back(scene.material(scene.meshPart(n).material).emissiveTexture.image);
    EXPECT_EQ(images, (std::vector<int>{0, 1}));
}

TEST(GltfMaterials, texcoord1TangentsAndEveryColourFormLoad) {
    QuadGltf q;
    q.primitives = R"([
        {"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_1": 3, "TANGENT": 7, "COLOR_0": 4}, "indices": 9},
        {"attributes": {"POSITION": 0, "COLOR_0": 5}, "indices": 9},
        {"attributes": {"POSITION": 0, "COLOR_0": 6}, "indices": 9}])";
    const auto l = load(q);
    const Geometry& a = l->geometry(0);
    ASSERT_EQ(a.texcoords1.size(), 4u);
    EXPECT_EQ(a.texcoords1[1], glm::vec2(0.0f, 1.0f));
    EXPECT_TRUE(a.texcoords.empty());
    ASSERT_EQ(a.tangents.size(), 4u);
    // Made unit length, w made a sign; from the file, not generated.
    expectTangent(a.tangents[2], {-1, 0, 0, -1});
    EXPECT_FALSE(a.tangentsGenerated);
    ASSERT_EQ(a.colors.size(), 4u);
    EXPECT_EQ(a.colors[0], glm::vec4(1, 0, 0, 1));
    EXPECT_EQ(a.colors[3], glm::vec4(1, 1, 1, 0));
    const Geometry& b = l->geometry(1);
    ASSERT_EQ(b.colors.size(), 4u);
    EXPECT_EQ(b.colors[3], glm::vec4(0.5f, 0.5f, 0.5f, 1.0f));  // VEC3: opaque
    const Geometry& c = l->geometry(2);
    ASSERT_EQ(c.colors.size(), 4u);
    EXPECT_EQ(c.colors[1], glm::vec4(0, 1, 0, 1));
    EXPECT_EQ(c.colors[3], glm::vec4(0, 0, 0, 0));
}

TEST(GltfMaterials, tangentsWithoutNormalsAreIgnoredAsTheSpecSays) {
    QuadGltf q;
    q.primitives = R"([{"attributes": {"POSITION": 0, "TANGENT": 7}, "indices": 9}])";
    const auto l = load(q);
    EXPECT_TRUE(l->geometry().tangents.empty());
    EXPECT_TRUE(l->warned("/meshes/0/primitives/0/attributes/TANGENT: ignored")) << l->model.warnings.size();
}

TEST(GltfMaterials, aNormalMapWithoutTangentsGetsThemGenerated) {
    QuadGltf q;
    q.materials = R"([{"normalTexture": {"index": 0}}])";
    const auto l = load(q);
    const Geometry& g = l->geometry();
    ASSERT_EQ(g.tangents.size(), 4u);
    EXPECT_TRUE(g.tangentsGenerated);
    for (const glm::vec4& t : g.tangents) expectTangent(t, {1, 0, 0, 1});
}

TEST(GltfMaterials, generatedTangentsFollowTheNormalMapsTexcoordSet) {
    // TEXCOORD_1 runs u the other way: the frame is mirrored.
    QuadGltf q;
    q.primitives = kWithUv1;
    q.materials = R"([{"normalTexture": {"index": 0, "texCoord": 1}}])";
    const auto l = load(q);
    ASSERT_EQ(l->geometry().tangents.size(), 4u);
    for (const glm::vec4& t : l->geometry().tangents) expectTangent(t, {-1, 0, 0, -1});
}

TEST(GltfMaterials, tangentsInTheFileAreKeptForANormalMap) {
    QuadGltf q;
    q.primitives =
        R"([{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2, "TANGENT": 7}, "indices": 9, "material": 0}])";
    q.materials = R"([{"normalTexture": {"index": 0}}])";
    const auto l = load(q);
    EXPECT_FALSE(l->geometry().tangentsGenerated);
    expectTangent(l->geometry().tangents[0], {-1, 0, 0, -1});
}

TEST(GltfMaterials, noTangentsWithoutANormalMap) {
    QuadGltf q;
    q.materials = R"([{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}])";
    const auto l = load(q);
    EXPECT_TRUE(l->geometry().tangents.empty());
    EXPECT_FALSE(l->geometry().tangentsGenerated);
}

TEST(GltfMaterials, aTextureOnATexcoordSetThePrimitiveLacksIsDroppedForThatPrimitiveOnly) {
    QuadGltf q;
    q.primitives = R"([
        {"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 9, "material": 0},
        {"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2, "TEXCOORD_1": 3}, "indices": 9, "material": 0}])";
    q.materials = R"([{"name": "stone", "normalTexture": {"index": 0, "texCoord": 1},
                       "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}])";
    const auto l = load(q);
    const Material& without = l->materialOfMesh(0);
    EXPECT_FALSE(without.normalTexture.present());
    EXPECT_TRUE(without.baseColorTexture.present());
    EXPECT_EQ(without.name, "stone");
    EXPECT_TRUE(l->geometry(0).tangents.empty());  // no normal map left to need them
    EXPECT_TRUE(l->warned("/meshes/0/primitives/0: material 0 ('stone') maps its normal texture with TEXCOORD_1, "
                          "which the primitive lacks"));
    EXPECT_TRUE(l->materialOfMesh(1).normalTexture.present());
    EXPECT_EQ(l->geometry(1).tangents.size(), 4u);
    EXPECT_EQ(l->model.warnings.size(), 1u);
}

TEST(GltfMaterials, aTextureOnTexcoord2IsDroppedWithAWarning) {
    QuadGltf q;
    q.materials = R"([{"name": "far", "occlusionTexture": {"index": 0, "texCoord": 2},
                       "emissiveTexture": {"index": 0}}])";
    const auto l = load(q);
    const Material& m = l->materialOfMesh();
    EXPECT_FALSE(m.occlusionTexture.present());
    EXPECT_TRUE(m.emissiveTexture.present());
    EXPECT_TRUE(l->warned("/materials/0/occlusionTexture: reads TEXCOORD_2"));
    EXPECT_TRUE(l->warned("material 0 ('far') drawn without its occlusion texture"));
}

TEST(GltfMaterials, anImageThatDoesNotDecodeCostsOnlyItsTexture) {
    QuadGltf q;
    q.images = R"([{"uri": "data:image/png;base64,AAAAAAAA"}])";
    q.materials = R"([{"normalTexture": {"index": 0}, "emissiveFactor": [1, 0, 0]}])";
    const auto l = load(q);
    const Material& m = l->materialOfMesh();
    EXPECT_FALSE(m.normalTexture.present());
    EXPECT_EQ(m.emissive, glm::vec3(1, 0, 0));
    EXPECT_TRUE(l->geometry().tangents.empty());
    EXPECT_TRUE(l->warned("image 0"));
}

TEST(GltfMaterials, badReferencesFailWithTheirPointer) {
    const auto withMaterial = [](const std::string& material) {
        QuadGltf q;
        q.materials = "[" + material + "]";
        return q;
    };
    expectMaterialRejected(withMaterial(R"({"normalTexture": {"index": 3}})"), "/materials/0/normalTexture/index",
                           "texture 3 does not exist (1 textures)");
    expectMaterialRejected(withMaterial(R"({"occlusionTexture": {"index": 1}})"), "/materials/0/occlusionTexture/index",
                           "texture 1 does not exist");
    expectMaterialRejected(withMaterial(R"({"emissiveTexture": {"index": 9}})"), "/materials/0/emissiveTexture/index",
                           "does not exist");
    expectMaterialRejected(withMaterial(R"({"pbrMetallicRoughness": {"metallicRoughnessTexture": {"index": 2}}})"),
                           "/materials/0/pbrMetallicRoughness/metallicRoughnessTexture/index", "does not exist");
    expectMaterialRejected(
        withMaterial(R"({"pbrMetallicRoughness": {"baseColorTexture": {"index": 0, "texCoord": -1}}})"),
        "/materials/0/pbrMetallicRoughness/baseColorTexture/texCoord", "expected 0 or more");
    expectMaterialRejected(
        withMaterial(R"({"emissiveTexture": {"index": 0, "extensions": {"KHR_texture_transform": {"offset": [1]}}}})"),
        "/materials/0/emissiveTexture/extensions/KHR_texture_transform/offset", "2 numbers");
    expectMaterialRejected(
        withMaterial(
            R"({"emissiveTexture": {"index": 0, "extensions": {"KHR_texture_transform": {"texCoord": 0.5}}}})"),
        "/materials/0/emissiveTexture/extensions/KHR_texture_transform/texCoord", "integer");
    expectMaterialRejected(
        withMaterial(R"({"extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": -1}}})"),
        "/materials/0/extensions/KHR_materials_emissive_strength/emissiveStrength", "negative");

    // Textures and samplers are checked whether a material uses them or not.
    QuadGltf q;
    q.textures = R"([{"source": 0}, {"source": 4}])";
    expectMaterialRejected(q, "/textures/1/source", "image 4 does not exist (1 images)");
    q.textures = R"([{"source": 0, "sampler": 2}])";
    q.samplers = "[{}]";
    expectMaterialRejected(q, "/textures/0/sampler", "sampler 2 does not exist (1 samplers)");
    q.samplers = R"([{"magFilter": 9984}])";  // a mipmap filter cannot magnify
    expectMaterialRejected(q, "/samplers/0/magFilter", "is 9984, expected 9728 (NEAREST) or 9729 (LINEAR)");
    q.samplers = R"([{"minFilter": 1}])";
    expectMaterialRejected(q, "/samplers/0/minFilter", "is 1");
    q.samplers = R"([{"wrapT": 10496}])";
    expectMaterialRejected(q, "/samplers/0/wrapT", "is 10496, expected 10497 (REPEAT)");
}

TEST(GltfMaterials, colourOfIntegersMustBeNormalized) {
    QuadGltf q;
    q.primitives = R"([{"attributes": {"POSITION": 0, "COLOR_0": 8}, "indices": 9}])";
    expectMaterialRejected(q, "/accessors/8/normalized", "must be normalized");
    q.primitives = R"([{"attributes": {"POSITION": 0, "COLOR_0": 2}, "indices": 9}])";
    expectMaterialRejected(q, "/accessors/2/type", "is VEC2, expected VEC3 or VEC4");
}

TEST(GltfMaterials, theNewExtensionsMayBeRequired) {
    QuadGltf q;
    q.extensionsUsed = R"(["KHR_texture_transform", "KHR_materials_emissive_strength", "KHR_materials_unlit"])";
    q.extensionsRequired = q.extensionsUsed;
    q.materials = R"([{"extensions": {"KHR_materials_unlit": {}}}])";
    EXPECT_TRUE(load(q)->materialOfMesh().unlit);
    q.extensionsRequired = R"(["KHR_materials_volume"])";
    expectMaterialRejected(q, "/extensionsRequired/0", "KHR_materials_volume");
}
