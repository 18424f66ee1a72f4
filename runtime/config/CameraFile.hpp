#pragma once
// A calibrated camera on disk: what `arcomp calibrate` writes and a
// station's `camera.calibration` names. YAML, in OpenCV's units and axes:
//
//   image_size: [768, 576]
//   fx: 720.5
//   fy: 719.8
//   cx: 383.2
//   cy: 290.1
//   distortion: [-0.12, 0.03, 0, 0, 0]        # k1, k2, p1, p2, k3
//   rotation: [1, 0, 0, 0, -0.34, -0.94, 0, 0.94, -0.34]   # floor to camera, row by row
//   translation: [0, 0.5, 9.1]                            # metres
//
//   writeCameraFile("camera.yaml", camera, "floor from 6 points, 0.8 px RMS");
//   CalibratedCamera camera = readCameraFile("camera.yaml");   // throws ConfigError with line:column
//
// Without rotation and translation the camera stands at the floor frame's
// origin looking along +z: a lens file, what `arcomp calibrate intrinsics`
// writes and `calibrate floor --intrinsics` reads.
//
//   writeLensFile("lens.yaml", intrinsics, "chessboard, 24 views, 0.31 px RMS");

#include "graph/camera/CalibratedCamera.hpp"

#include <filesystem>
#include <string>

namespace arcomp {

// `note` becomes a comment at the top (how the calibration was made).
// Replaces the file atomically; throws std::runtime_error when it cannot.
void writeCameraFile(const std::filesystem::path& file, const CalibratedCamera& camera, const std::string& note);
// The lens alone (no rotation, no translation): a pose written with it
// would claim the camera stands on the floor.
void writeLensFile(const std::filesystem::path& file, const CameraIntrinsics& intrinsics, const std::string& note);
CalibratedCamera readCameraFile(const std::filesystem::path& file);

}  // namespace arcomp
