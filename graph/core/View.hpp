#pragma once
// A camera as the select pass and the renderer see it: matrices, eye and
// the viewport in pixels.
//
//   View v = View::lookAt({0, 1, 5}, {0, 0, 0}, {0, 1, 0}, 60.0f, {1280, 720});
//   View f = View::framing(scene.bound(), 60.0f, {640, 480});

#include "graph/core/Bounds.hpp"

namespace arcomp {

struct View {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::vec3 eye{0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f};
    glm::ivec2 viewport{640, 480};
    float fovyRadians = 1.0f;
    float near = 0.1f;
    float far = 1000.0f;

    glm::mat4 viewProjection() const { return projection * view; }
    // Pixels per unit of size at unit distance, vertically; a sphere of
    // radius r at distance d spans r / d * pixelsPerRadian() pixels.
    float pixelScale() const;
    // Projected area of a sphere in pixels (the disc it covers, clamped to
    // the viewport); cheap enough for every object every frame.
    float projectedArea(const Sphere& s) const;

    static View lookAt(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up, float fovyDegrees,
                       glm::ivec2 viewport, float near = 0.1f, float far = 1000.0f);
    // Looks at the sphere from +Z, slightly above, at a distance where it fills
    // about 80% of the view height; near and far bracket it.
    static View framing(const Sphere& s, float fovyDegrees, glm::ivec2 viewport);
};

}  // namespace arcomp
