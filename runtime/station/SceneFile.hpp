#pragma once
// What `render`, `inspect` and the station draw: a single model file, or the
// scene a station config describes (with its camera and background).
//
//   SceneFile f = loadSceneFile("bunny.obj");          // throws ModelError
//   SceneFile g = loadSceneFile("station.yaml");       // throws ConfigError

#include "graph/animation/Skin.hpp"
#include "graph/core/View.hpp"
#include "graph/core/World.hpp"
#include "runtime/config/StationConfig.hpp"
#include "runtime/station/BakeCache.hpp"

#include <optional>

namespace arcomp {

struct SceneFile {
    // The scene and its tables: a config's LOD, grouping, movers and point
    // clouds; a model file's meshes alone.
    World world;
    std::optional<View> camera;
    glm::vec4 background{0.0f};
    // A config's render.environment and its intensity; empty: neutral.
    std::filesystem::path environment;
    float environmentIntensity = 1.0f;
    // Models a config names that could not be loaded are skipped, each with
    // a line here: the station goes on with the rest.
    std::vector<std::string> warnings;
    std::vector<std::string> notDrawn;  // a model file's extensions arcomp leaves out
    // A model file's glTF animations and skins (a config's objects play
    // theirs through world.animations instead).
    std::vector<ModelAnimation> animations;
    std::vector<Skin> skins;
};

SceneFile loadSceneFile(const std::filesystem::path& file);
// Adds the config's objects to the world; failures become warnings. Objects
// with `lod` get an LOD node per mesh, objects with `motion` a mover, those
// with `animation` a player (an unknown animation skips the object), and
// the grouping and point_clouds sections their nodes. The LOD levels are
// generated at load, or loaded from `bakeCache` when they were generated
// there before from the same mesh and ratios (runtime/station/BakeCache.hpp);
// without a folder they are generated every time. Returns how the levels
// came.
BakeTally buildScene(const StationConfig& cfg, World& world, std::vector<std::string>& warnings,
                     const std::filesystem::path& bakeCache = {});
View cameraView(const CameraConfig& camera);

}  // namespace arcomp
