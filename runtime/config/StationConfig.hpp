#pragma once
// One installation, as its YAML file describes it. Field-by-field
// documentation: configs/README.md. Loading validates everything at once and
// throws ConfigError listing every problem with its line and column.
//
//   StationConfig cfg = loadStationConfig("configs/demo-replay.yaml");

#include "graph/camera/CalibratedCamera.hpp"
#include "graph/core/Shading.hpp"
#include "graph/lod/Lod.hpp"
#include "runtime/config/BudgetConfig.hpp"
#include "runtime/config/CompositingConfig.hpp"
#include "runtime/config/GazeConfig.hpp"
#include "runtime/config/GroupingConfig.hpp"
#include "runtime/config/OperatorConfig.hpp"
#include "runtime/config/PointCloudConfig.hpp"
#include "runtime/config/ShowControlConfig.hpp"
#include "runtime/triggers/Trigger.hpp"
#include "runtime/zones/Zone.hpp"

#include <glm/glm.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace arcomp {

// A thing in the scene: a model file or a built-in shape, placed by
// position, rotation (degrees about X, then Y, then Z) and scale.
struct ObjectConfig {
    std::string name;
    std::filesystem::path model;  // empty for shapes
    std::string shape;            // "box" or "sphere" when no model
    glm::vec3 size{1.0f};         // box edge lengths
    float radius = 0.5f;          // sphere
    glm::vec4 color{0.8f, 0.8f, 0.8f, 1.0f};
    glm::vec3 position{0.0f};
    glm::vec3 rotationDegrees{0.0f};
    glm::vec3 scale{1.0f};
    // Generated levels of detail (graph/lod/LodLevels.hpp), one LOD node per
    // mesh, chosen by `policy`; empty ratios: no LOD.
    std::vector<float> lodRatios;      // finest first; the first is 1
    std::vector<float> lodThresholds;  // ratios.size() - 1 boundaries
    LodPolicy lodPolicy = LodPolicy::Distance;
    float lodFadeSeconds = 0.0f;
    // A mover (graph/core/ObjectMotion.hpp): back and forth along the velocity.
    glm::vec3 velocity{0.0f};
    float rangeMetres = 0.0f;
    // A glTF animation of the model to play on the video's clock, by name or
    // index; empty: none plays, even when the model has some.
    std::string animation;
    bool animationLoop = true;
    float animationSpeed = 1.0f;
    bool animationPlaying = true;  // false: held at its start until a trigger or a cue plays it
    bool visible = true;           // false: hidden until a trigger or a cue shows it
    int line = 0;                  // where it was declared, for messages about it later
};

struct CameraConfig {
    bool given = false;
    // With `calibration`, the real camera's pose and intrinsics
    // (runtime/config/CameraFile.hpp) replace eye, target, up and fovy_deg.
    std::filesystem::path calibration;
    std::optional<CalibratedCamera> calibrated;
    glm::vec3 eye{0.0f, 1.6f, 5.0f};
    glm::vec3 target{0.0f, 1.0f, 0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovyDegrees = 45.0f;
    glm::ivec2 size{1280, 720};
    float near = 0.1f;
    float far = 500.0f;
};

struct RenderConfig {
    Shading shading = Shading::Phong;
    std::string gl = "auto";
    glm::vec4 background{0.08f, 0.08f, 0.1f, 1.0f};
    // The image-based light: an equirectangular .hdr or .png, empty for the
    // built-in neutral studio (runtime/render/Environment.hpp). A file that cannot
    // be read fails `arcomp check` and a reload; at start the station says so
    // and lights with the neutral one.
    std::filesystem::path environment;
    float environmentIntensity = 1.0f;
};

struct StationConfig {
    std::filesystem::path file;
    std::vector<ObjectConfig> objects;
    CameraConfig camera;
    RenderConfig render;
    CompositingConfig compositing;  // video, matte, compositor, output
    OperatorConfig operation;
    BudgetConfig budget;
    GroupingConfig grouping;
    GazeConfig gaze;
    PointCloudConfig pointClouds;
    ShowControlConfig showControl;  // where the people are sent
    std::vector<Zone> zones;        // where visitors are counted
    std::vector<Trigger> triggers;  // what visitors set off (runtime/config/TriggerConfig.hpp)
};

StationConfig loadStationConfig(const std::filesystem::path& file);

}  // namespace arcomp
