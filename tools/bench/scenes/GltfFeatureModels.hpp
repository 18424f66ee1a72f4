#pragma once
// The glTF feature models: one small, self-contained .gltf per material or
// animation feature that a station's renderer must draw like every other
// glTF viewer does (emission, normal maps, MASK and BLEND, texture
// transforms, metallic/roughness, vertex colours, node animation, skinning),
// and glTF as pipelines ship it (Draco, meshopt and quantized copies of a
// textured ball, a WebP-textured plane). Buffers and images are data URIs,
// so a model is one file that any viewer opens; the meshopt and quantized
// copies are gltfpack's .glb of another model. Each model carries how it is to be looked at: camera,
// directional light, environment and, when animated, the times to show.
// `arcomp-bench gltf-reference` renders them with arcomp and with three.js
// and compares; the tests load them with arcomp's loader.
//
//   for (const FeatureModel& m : featureModels())
//       fs::path file = writeFeatureModel(m, "build/feature-models");  // .../emissive.gltf, ...

#include <glm/glm.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace arcomp {

struct FeatureCamera {
    glm::vec3 eye{0.0f, 0.0f, 3.0f};
    glm::vec3 target{0.0f};
    float fovyDegrees = 40.0f;  // vertical; up is +Y
    float near = 0.1f;
    float far = 100.0f;
};

// glTF's KHR_lights_punctual convention, which three.js follows: a white
// Lambertian surface facing a light of intensity I (lux) reflects I / pi.
struct FeatureLight {
    glm::vec3 direction{0.0f, 0.0f, 1.0f};  // towards the light, world space
    glm::vec3 color{1.0f};                  // linear
    float intensity = 3.0f;
};

struct FeatureModel {
    std::string name;     // the file's stem
    std::string feature;  // what it shows, one line
    FeatureCamera camera;
    FeatureLight light;
    std::string environment;  // "neutral" (image-based light), or empty for none
    float environmentIntensity = 1.0f;
    std::vector<float> times{};  // seconds into the animation to show; empty when nothing moves
    std::string packedFrom{};    // a gltfpack copy of this model, or empty
    std::string packOptions{};   // gltfpack's options for the copy: "-c -noq" meshopt, "" quantized
};

// Every feature model, in a fixed order.
const std::vector<FeatureModel>& featureModels();

// The model's glTF JSON, buffers and images embedded. Throws
// std::invalid_argument for a name featureModels() does not have, or for a
// gltfpack copy (writeFeatureModel makes those).
std::string featureModelGltf(const std::string& name);

// Writes <folder>/<name>.gltf (creating the folder) and returns its path;
// a gltfpack copy is <folder>/<name>.glb, made from its source's .gltf.
// Throws std::runtime_error naming the file when it cannot be written, or
// gltfpack when it is missing or fails.
std::filesystem::path writeFeatureModel(const FeatureModel& model, const std::filesystem::path& folder);

}  // namespace arcomp
