#pragma once
// What `render`, `inspect` and the station draw: a single model file, or the
// scene a station config describes (with its camera and background).
//
//   SceneFile f = loadSceneFile("bunny.obj");          // throws ModelError
//   SceneFile g = loadSceneFile("station.yaml");       // throws ConfigError

#include "graph/grouping/GroupingNodes.hpp"
#include "graph/lod/Lod.hpp"
#include "graph/core/ObjectMotion.hpp"
#include "graph/points/PointCloudNodes.hpp"
#include "graph/core/Scene.hpp"
#include "graph/core/View.hpp"
#include "runtime/StationConfig.hpp"

#include <optional>

namespace arcomp {

struct SceneFile {
    Scene scene;
    std::optional<View> camera;
    glm::vec4 background{0.0f};
    // Models a config names that could not be loaded are skipped, each with
    // a line here: the station goes on with the rest.
    std::vector<std::string> warnings;
    // Side tables of the grouping section's nodes (empty without one).
    GroupingNodes grouping;
    LodTable lods;
    // The point_clouds section's clouds (empty without one).
    PointCloudNodes pointClouds;
};

SceneFile loadSceneFile(const std::filesystem::path& file);
// Adds the config's objects to a scene; failures become warnings.
// With tables, the config's grouping section (if any) fills them; without,
// grouped content is still added and draws at full detail.
// Objects with `lod` get an LOD node per mesh (levels generated at load)
// in `lods`; objects with `motion` are listed in `motions`. With a cloud
// table, the point_clouds section's clouds are added; without, none.
void buildScene(const StationConfig& cfg, Scene& scene, std::vector<std::string>& warnings,
                GroupingNodes* grouping = nullptr, LodTable* lods = nullptr, std::vector<ObjectMotion>* motions = nullptr,
                PointCloudNodes* clouds = nullptr);
View cameraView(const CameraConfig& camera);

} // namespace arcomp
