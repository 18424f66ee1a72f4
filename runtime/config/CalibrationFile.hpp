#pragma once
// The cost model's calibration on disk: what `arcomp-bench calibrate`
// writes and a station's `budget.calibration` names. YAML, one entry per
// LOD level with [A ms/pixel, B ms] per shading, and the frame overhead:
//
//   device: "gl33: 4.5 (Core Profile) Mesa 22.3.6 on llvmpipe (LLVM 15.0.6, 256 bits)"
//   viewport: [1280, 720]
//   overhead_ms: 0.9
//   levels:
//     - {unlit: [1.1e-06, 0.4], flat: [2.0e-06, 0.4], gouraud: [1.9e-06, 0.5], phong: [3.2e-06, 0.5]}
//
//   writeCalibration("calib.yaml", model, {glDescription(), {1280, 720}});
//   CostModel m = readCalibration("calib.yaml");   // throws ConfigError with line:column

#include "graph/budget/CostModel.hpp"

#include <glm/glm.hpp>

#include <filesystem>
#include <string>

namespace arcomp {

struct CalibrationInfo {
    std::string device;      // the GL context it was measured on
    glm::ivec2 viewport{0};  // the output size it was measured at
};

// Throws std::runtime_error when the file cannot be written.
void writeCalibration(const std::filesystem::path& file, const CostModel& model, const CalibrationInfo& info);
// Throws ConfigError listing every problem with its place.
CostModel readCalibration(const std::filesystem::path& file, CalibrationInfo* info = nullptr);

}  // namespace arcomp
