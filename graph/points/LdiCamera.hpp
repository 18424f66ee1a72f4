#pragma once
// The reference camera of a layered depth image: a perspective pinhole with
// square pixels. Camera coordinates are x right, y down, z forward, so a
// pixel's column and row grow with x and y; the screen lies at distance
// `focal` (in pixels) in front of the eye, which is the paper's D0.
//
//   LdiCamera c = LdiCamera::lookAt(eye, target, {0, 1, 0}, 40.0f, 256, 256);
//   glm::vec3 q = c.toCamera(p);   // q.z is p's depth, q.x / q.z * focal + cx its column
//   auto cams = ldiCamerasAround(bound, 6, voxelSize);

#include "graph/core/Bounds.hpp"

#include <glm/glm.hpp>

#include <vector>

namespace arcomp {

struct LdiCamera {
    glm::vec3 eye{0.0f};
    glm::mat3 rotation{1.0f};  // world direction -> camera axes (rows: right, down, forward)
    float focal = 1.0f;        // pixels from the eye to the screen
    int width = 1;
    int height = 1;

    glm::vec3 toCamera(const glm::vec3& p) const { return rotation * (p - eye); }
    glm::vec2 principal() const { return {static_cast<float>(width) * 0.5f, static_cast<float>(height) * 0.5f}; }
    // Unit world direction of the ray through pixel (x, y)'s centre.
    glm::vec3 rayDirection(int x, int y) const;

    static LdiCamera lookAt(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up, float fovyDegrees,
                            int width, int height);
};

// `count` cameras around the sphere, each framing all of it, with as many
// pixels as make one pixel `pixelSize` wide at the sphere's centre. One
// camera looks from the front (+z, slightly above); six sit on the axes,
// around the model as in the paper; other counts spread over a sphere.
std::vector<LdiCamera> ldiCamerasAround(const Sphere& bound, int count, float pixelSize);

}  // namespace arcomp
