#pragma once
// The config's `gaze` section: where the viewer looks, for the gaze LOD
// policies and the frame-time controller's importance. Absent: the screen
// centre (the view's forward direction).
//
//   gaze: {source: track, track: session.csv}     # a recorded track, for replay
//   gaze: {source: fixed, direction: [0.3, 0, -1]}

#include <glm/vec3.hpp>

#include <filesystem>

namespace arcomp {

class YamlMap;

enum class GazeKind { ScreenCentre, Fixed, Track };

struct GazeConfig {
    GazeKind kind = GazeKind::ScreenCentre;
    glm::vec3 direction{0.0f, 0.0f, -1.0f};  // fixed: world space
    std::filesystem::path track;             // track: CSV (runtime/station/GazeSource.hpp)
};

void readGazeConfig(YamlMap& root, GazeConfig& out);

}  // namespace arcomp
