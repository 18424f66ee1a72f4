// The glTF feature models of `arcomp-bench gltf-reference`: each is a glTF
// file arcomp's loader takes without a warning, shows the feature it is
// named after, and sits inside its own camera's view.
#include "tools/bench/scenes/GltfFeatureModels.hpp"

#include "graph/core/View.hpp"
#include "graph/io/ModelLoader.hpp"

#include "../support/TempDir.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <fstream>
#include <set>
#include <stdexcept>

namespace arcomp {
namespace {

using test::TempDir;

// The model's glTF as a document (yaml-cpp reads JSON).
YAML::Node document(const std::string& name) { return YAML::Load(featureModelGltf(name)); }

TEST(GltfFeatureModels, everyFeatureOfTheIssueHasAModel) {
    std::set<std::string> names;
    for (const FeatureModel& m : featureModels()) EXPECT_TRUE(names.insert(m.name).second) << m.name << " twice";
    for (const char* name :
         {"emissive", "emissive-unlit", "normal-map", "alpha-mask", "alpha-blend", "texture-transform", "metal-rough",
          "vertex-colors", "animated-node", "skinned-bend", "checker-ball", "checker-ball-draco",
          "checker-ball-meshopt", "checker-ball-quantized", "webp-plane"})
        EXPECT_TRUE(names.count(name)) << name;
}

TEST(GltfFeatureModels, eachLoadsWithoutWarnings) {
    TempDir dir;
    for (const FeatureModel& m : featureModels()) {
        const auto file = writeFeatureModel(m, dir.path());
        EXPECT_EQ(file, dir.path() / (m.name + (m.packedFrom.empty() ? ".gltf" : ".glb")));
        Scene scene;
        const LoadedModel loaded = loadModel(file, scene, scene.root());
        for (const std::string& w : loaded.warnings) ADD_FAILURE() << m.name << ": " << w;
        scene.update();
        EXPECT_FALSE(scene.bound().empty()) << m.name << " has nothing to draw";
    }
}

// The model's bound (at rest) is in front of the camera and its centre in
// the picture: a wrong eye or target would show an empty frame.
TEST(GltfFeatureModels, eachIsInItsCamerasView) {
    TempDir dir;
    for (const FeatureModel& m : featureModels()) {
        Scene scene;
        loadModel(writeFeatureModel(m, dir.path()), scene, scene.root());
        scene.update();
        const Sphere b = scene.bound();
        const View view = View::lookAt(m.camera.eye, m.camera.target, {0, 1, 0}, m.camera.fovyDegrees, {480, 360},
                                       m.camera.near, m.camera.far);
        const glm::vec4 clip = view.viewProjection() * glm::vec4(b.center, 1.0f);
        ASSERT_GT(clip.w, b.radius) << m.name << " is not wholly in front of the camera";
        EXPECT_LT(std::abs(clip.x / clip.w), 0.5f) << m.name;
        EXPECT_LT(std::abs(clip.y / clip.w), 0.5f) << m.name;
        EXPECT_LT(glm::length(m.camera.eye - b.center) + b.radius, m.camera.far) << m.name;
        EXPECT_NEAR(glm::length(m.light.direction), 1.0f, 1e-5f) << m.name;
    }
}

TEST(GltfFeatureModels, materialsAreTheFeature) {
    TempDir dir;
    const auto materials = [&](const std::string& name) {
        Scene scene;
        for (const FeatureModel& m : featureModels())
            if (m.name == name) loadModel(writeFeatureModel(m, dir.path()), scene, scene.root());
        return scene.materials();
    };
    const auto mask = materials("alpha-mask");
    ASSERT_FALSE(mask.empty());
    EXPECT_EQ(mask[0].alphaMode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(mask[0].alphaCutoff, 0.5f);
    EXPECT_TRUE(mask[0].baseColorTexture.present());

    bool blend = false, opaque = false;
    for (const Material& m : materials("alpha-blend")) {
        blend = blend || (m.alphaMode == AlphaMode::Blend && m.baseColor.a == 0.5f);
        opaque = opaque || (m.name == "opaque" && m.alphaMode == AlphaMode::Opaque);
    }
    EXPECT_TRUE(blend && opaque);

    const auto emissive = materials("emissive");
    ASSERT_FALSE(emissive.empty());
    EXPECT_EQ(emissive[0].baseColor, glm::vec4(0, 0, 0, 1));
    EXPECT_FALSE(emissive[0].unlit);

    bool unlitLamp = false;
    for (const Material& m : materials("emissive-unlit"))
        unlitLamp = unlitLamp || (m.unlit && m.baseColor == glm::vec4(0, 0, 0, 1));
    EXPECT_TRUE(unlitLamp);
}

TEST(GltfFeatureModels, documentsCarryWhatTheLoaderDoesNotReadYet) {
    const YAML::Node emissive = document("emissive");
    EXPECT_EQ(emissive["materials"][0]["emissiveFactor"][1].as<float>(), 0.45f);

    const YAML::Node normal = document("normal-map");
    EXPECT_TRUE(normal["materials"][0]["normalTexture"].IsDefined());
    EXPECT_TRUE(normal["meshes"][0]["primitives"][0]["attributes"]["NORMAL"].IsDefined());
    EXPECT_FALSE(normal["meshes"][0]["primitives"][0]["attributes"]["TANGENT"].IsDefined())
        << "tangents are left for the viewer to generate";

    const YAML::Node transform =
        document("texture-transform")["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]
                                     ["KHR_texture_transform"];
    EXPECT_EQ(transform["scale"][0].as<float>(), transform["scale"][1].as<float>())
        << "three.js orders a non-uniform scale differently";
    EXPECT_NE(transform["rotation"].as<float>(), 0.0f);

    const YAML::Node sweep = document("metal-rough");
    ASSERT_EQ(sweep["materials"].size(), 10u);
    std::set<std::pair<float, float>> grid;
    for (const auto& m : sweep["materials"])
        grid.insert({m["pbrMetallicRoughness"]["metallicFactor"].as<float>(),
                     m["pbrMetallicRoughness"]["roughnessFactor"].as<float>()});
    EXPECT_EQ(grid.size(), 10u);
    EXPECT_TRUE(grid.count({1.0f, 0.0f}) && grid.count({0.0f, 1.0f}));

    EXPECT_TRUE(document("vertex-colors")["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"].IsDefined());

    for (const char* name : {"animated-node", "skinned-bend"}) {
        const YAML::Node animation = document(name)["animations"][0];
        ASSERT_TRUE(animation.IsDefined()) << name;
        for (const auto& sampler : animation["samplers"])
            EXPECT_EQ(sampler["interpolation"].as<std::string>(), "LINEAR");
    }
    const YAML::Node skinned = document("skinned-bend");
    EXPECT_EQ(skinned["skins"][0]["joints"].size(), 2u);
    EXPECT_TRUE(skinned["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_0"].IsDefined());
}

TEST(GltfFeatureModels, animatedModelsAreShownAtTimesWithinTheirClip) {
    for (const FeatureModel& m : featureModels()) {
        const bool animated = m.name == "animated-node" || m.name == "skinned-bend";
        EXPECT_EQ(!m.times.empty(), animated) << m.name;
        for (float t : m.times) {
            EXPECT_GE(t, 0.0f) << m.name;
            EXPECT_LE(t, 2.0f) << m.name;
        }
    }
}

TEST(GltfFeatureModels, unknownNameThrows) {
    EXPECT_THROW(featureModelGltf("teapot"), std::invalid_argument);
    EXPECT_THROW(featureModelGltf("checker-ball-meshopt"), std::invalid_argument);  // gltfpack makes it
}

// Each compressed copy of the ball uses its extension and draws the
// ball's triangles; the WebP plane's texture decodes.
TEST(GltfFeatureModels, theCompressedCopiesAreTheBallCompressed) {
    TempDir dir;
    const auto parsed = [&](const std::string& name) {
        for (const FeatureModel& m : featureModels())
            if (m.name == name) {
                const auto file = writeFeatureModel(m, dir.path());
                std::ifstream in(file, std::ios::binary);
                return std::pair{parseModel(file), std::string{std::istreambuf_iterator<char>(in), {}}};
            }
        throw std::invalid_argument(name);
    };
    const auto triangles = [](const ParsedModel& m) {
        std::size_t n = 0;
        for (const Geometry& g : m.geometries) n += g.triangleCount();
        return n;
    };
    const std::size_t ball = triangles(parsed("checker-ball").first);
    for (const auto& [name, extension] : {std::pair{"checker-ball-draco", "KHR_draco_mesh_compression"},
                                          std::pair{"checker-ball-meshopt", "EXT_meshopt_compression"},
                                          std::pair{"checker-ball-quantized", "KHR_mesh_quantization"}}) {
        const auto [model, bytes] = parsed(name);
        EXPECT_NE(bytes.find(extension), std::string::npos) << name;
        EXPECT_EQ(triangles(model), ball) << name;
        ASSERT_FALSE(model.images.empty()) << name;
        EXPECT_EQ(model.images[0].width, 256) << name;
    }
    const auto [plane, bytes] = parsed("webp-plane");
    EXPECT_NE(bytes.find("image/webp"), std::string::npos);
    ASSERT_EQ(plane.images.size(), 1u);
    EXPECT_EQ(plane.images[0].width, 128);
    EXPECT_EQ(plane.materials[0].baseColorTexture.image, 0);
}

}  // namespace
}  // namespace arcomp
