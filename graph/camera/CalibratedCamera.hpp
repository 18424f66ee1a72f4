#pragma once
// The real camera as calibration measured it: the pinhole intrinsics (focal
// lengths and principal point in pixels, and the lens distortion), and the
// camera's pose in the floor frame (metres, +Y up, the floor at y = 0).
// The CG camera is built from it, so that a CG point lands on the pixel
// where the real point at the same place appears.
//
//   CalibratedCamera camera = readCameraFile("station-camera.yaml");   // runtime/config/CameraFile.hpp
//   View view = camera.view(videoSize, 0.1f, 500.0f);
//
// Axes follow OpenCV (x right, y down, z forward from the lens), so that the
// numbers are those cv::calibrateCamera and cv::solvePnP give.

#include "graph/core/View.hpp"

#include <glm/glm.hpp>

#include <array>
#include <optional>

namespace arcomp {

struct CameraIntrinsics {
    glm::ivec2 imageSize{0};  // the size fx..cy were measured at
    double fx = 0.0, fy = 0.0;
    double cx = 0.0, cy = 0.0;
    std::array<double, 5> distortion{};  // k1, k2, p1, p2, k3

    bool distorted() const;
    // The same camera at another resolution (the video scaled): focal
    // lengths and principal point scale with the image.
    CameraIntrinsics scaledTo(glm::ivec2 size) const;
};

struct CalibratedCamera {
    CameraIntrinsics intrinsics;
    // Floor frame to camera: x_camera = rotation * x_floor + translation.
    glm::dmat3 rotation{1.0};
    glm::dvec3 translation{0.0};

    glm::dvec3 position() const;  // the lens centre in the floor frame
    double heightMetres() const;  // above the floor
    double tiltDegrees() const;   // of the optical axis below the horizon
    // Pixel where a floor-frame point appears, without distortion; z <= 0
    // (behind the lens) gives NaN.
    glm::dvec2 project(const glm::dvec3& floorPoint) const;
    // The floor point (y = 0) imaged at `pixel` (undistorted, at
    // intrinsics.imageSize): where a person whose feet are at that pixel
    // stands. None when the pixel's ray misses the floor (at or above the horizon).
    std::optional<glm::dvec3> floorPointAt(const glm::dvec2& pixel) const;
    // The direction, in the floor frame, of the ray from the lens centre
    // through `pixel` (undistorted, at intrinsics.imageSize); not normalised.
    glm::dvec3 rayThrough(const glm::dvec2& pixel) const;
    // Distance of a floor-frame point along the optical axis: the depth the
    // CG is compared with.
    double depthOf(const glm::dvec3& floorPoint) const;
    // The CG view: the real camera's pose, and a projection from its
    // intrinsics scaled to `viewport`.
    View view(glm::ivec2 viewport, float near, float far) const;
};

// An OpenGL projection matrix from pinhole intrinsics, for a viewport of
// intrinsics.imageSize, looking down -Z with +Y up in eye space.
glm::mat4 projectionFromIntrinsics(const CameraIntrinsics& intrinsics, float near, float far);

}  // namespace arcomp
