#include "graph/camera/CalibratedCamera.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace arcomp {

bool CameraIntrinsics::distorted() const {
    return std::any_of(distortion.begin(), distortion.end(), [](double d) { return d != 0.0; });
}

CameraIntrinsics CameraIntrinsics::scaledTo(glm::ivec2 size) const {
    if (size == imageSize || imageSize.x <= 0 || imageSize.y <= 0) return *this;
    CameraIntrinsics s = *this;
    const double sx = static_cast<double>(size.x) / imageSize.x, sy = static_cast<double>(size.y) / imageSize.y;
    // Pixel centres sit at integer coordinates (OpenCV's convention), so the
    // principal point scales about the image corner's half-pixel.
    s.fx *= sx;
    s.fy *= sy;
    s.cx = (cx + 0.5) * sx - 0.5;
    s.cy = (cy + 0.5) * sy - 0.5;
    s.imageSize = size;
    return s;
}

glm::dvec3 CalibratedCamera::position() const { return -glm::transpose(rotation) * translation; }

double CalibratedCamera::heightMetres() const { return position().y; }

double CalibratedCamera::tiltDegrees() const {
    // The optical axis (camera +z) in the floor frame is the rotation's third row.
    const glm::dvec3 axis = glm::transpose(rotation) * glm::dvec3(0.0, 0.0, 1.0);
    return glm::degrees(std::asin(std::clamp(-axis.y, -1.0, 1.0)));
}

glm::dvec2 CalibratedCamera::project(const glm::dvec3& floorPoint) const {
    const glm::dvec3 p = rotation * floorPoint + translation;
    if (p.z <= 0.0) return glm::dvec2(std::numeric_limits<double>::quiet_NaN());
    return {intrinsics.fx * p.x / p.z + intrinsics.cx, intrinsics.fy * p.y / p.z + intrinsics.cy};
}

glm::dvec3 CalibratedCamera::rayThrough(const glm::dvec2& pixel) const {
    const glm::dvec3 inCamera((pixel.x - intrinsics.cx) / intrinsics.fx, (pixel.y - intrinsics.cy) / intrinsics.fy,
                              1.0);
    return glm::transpose(rotation) * inCamera;
}

std::optional<glm::dvec3> CalibratedCamera::floorPointAt(const glm::dvec2& pixel) const {
    const glm::dvec3 direction = rayThrough(pixel);
    const glm::dvec3 origin = position();
    // Only a ray going down from above the floor meets it in front of the lens.
    if (origin.y <= 0.0 || direction.y >= -1e-9) return std::nullopt;
    return origin + (-origin.y / direction.y) * direction;
}

double CalibratedCamera::depthOf(const glm::dvec3& floorPoint) const { return (rotation * floorPoint + translation).z; }

glm::mat4 projectionFromIntrinsics(const CameraIntrinsics& k, float near, float far) {
    // Pinhole u = fx·X/Z + cx, v = fy·Y/Z + cy (OpenCV camera axes, pixel
    // centres at integers, v down) rewritten for GL eye space (X = x_e,
    // Y = -y_e, Z = -z_e) and NDC (x = 2(u + ½)/w − 1, y = 1 − 2(v + ½)/h):
    //   x_clip = 2fx/w·x_e + (1 − 2(cx + ½)/w)·z_e
    //   y_clip = 2fy/h·y_e + (2(cy + ½)/h − 1)·z_e,   w_clip = −z_e.
    const double w = k.imageSize.x, h = k.imageSize.y;
    glm::mat4 p(0.0f);
    p[0][0] = static_cast<float>(2.0 * k.fx / w);
    p[1][1] = static_cast<float>(2.0 * k.fy / h);
    p[2][0] = static_cast<float>(1.0 - 2.0 * (k.cx + 0.5) / w);
    p[2][1] = static_cast<float>(2.0 * (k.cy + 0.5) / h - 1.0);
    p[2][2] = -(far + near) / (far - near);
    p[2][3] = -1.0f;
    p[3][2] = -2.0f * far * near / (far - near);
    return p;
}

View CalibratedCamera::view(glm::ivec2 viewport, float near, float far) const {
    const CameraIntrinsics k = intrinsics.scaledTo(viewport);
    // OpenCV's camera looks down +z with y down; GL's looks down -z with y up.
    const glm::dmat4 flip(glm::dvec4(1, 0, 0, 0), glm::dvec4(0, -1, 0, 0), glm::dvec4(0, 0, -1, 0),
                          glm::dvec4(0, 0, 0, 1));
    glm::dmat4 floorToCamera(rotation);
    floorToCamera[3] = glm::dvec4(translation, 1.0);
    View v;
    v.view = glm::mat4(flip * floorToCamera);
    v.projection = projectionFromIntrinsics(k, near, far);
    v.eye = glm::vec3(position());
    v.forward = glm::vec3(glm::transpose(rotation) * glm::dvec3(0.0, 0.0, 1.0));
    v.viewport = viewport;
    v.fovyRadians = static_cast<float>(2.0 * std::atan(0.5 * viewport.y / k.fy));
    v.near = near;
    v.far = far;
    return v;
}

}  // namespace arcomp
