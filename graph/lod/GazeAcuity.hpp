#pragma once
// Visual acuity of an object as the viewer sees it, after the gaze-directed
// LOD paper (DESIGN.md §1): k1 falls off with the angle between the gaze and
// the object, k2 with how fast the object sweeps across the visual field.
// Their product, gazeAcuity(), picks the object's level through per-node
// thresholds (see graph/lod/Lod.hpp).
//
//   GazeAcuityParams p;                                        // a = 5°, c1 = 6°, c2 = 30°/s
//   float theta = angleDegrees(gaze, center - eye);
//   float speed = angularSpeed(last, worldNow, eyeNow, dt);     // degrees per second
//   float k = gazeAcuity(theta, speed, p);                      // in [0, 1]
//   last = trackPoint(eyeNow, worldNow, localCenter, radius);   // for the next frame
//
// The representative point is the point, nearest the eye, of the sphere with
// the object's mean radius. Its angular speed comes from where that point,
// fixed to the object, was last frame and where it is now; so it counts the
// object moving, the object rotating and the viewer moving alike.

#include <glm/glm.hpp>

#include <span>

namespace arcomp {

struct GazeAcuityParams {
    float foveaDegrees = 5.0f;  // a: full acuity within this angle of the gaze
    float c1Degrees = 6.0f;     // c1: e-folding angle of the fall-off beyond a
    // c2: angular speed at which detail is no longer perceived. The paper
    // leaves it open; 30°/s is about where smooth pursuit stops keeping the
    // image on the fovea and dynamic acuity has dropped several-fold.
    float c2DegreesPerSecond = 30.0f;
};

// Paper: gaze-directed-lod, equation (1). theta in degrees.
float eccentricityAcuity(float thetaDegrees, const GazeAcuityParams& p);

// Paper: gaze-directed-lod, equation (2). Angular speed in degrees per second.
float motionAcuity(float angularSpeedDegreesPerSecond, const GazeAcuityParams& p);

// The product k1·k2 that the paper's level selection reads.
inline float gazeAcuity(float thetaDegrees, float angularSpeedDegreesPerSecond, const GazeAcuityParams& p) {
    return eccentricityAcuity(thetaDegrees, p) * motionAcuity(angularSpeedDegreesPerSecond, p);
}

// Angle between two directions in degrees; 0 when either is zero.
float angleDegrees(const glm::vec3& a, const glm::vec3& b);

// The paper's stand-in sphere: mean distance of the vertices from `center`.
float meanRadius(std::span<const glm::vec3> positions, const glm::vec3& center);

// The point of the sphere (centre, mean radius) nearest the eye; the centre
// itself when the eye is inside the sphere.
glm::vec3 representativePoint(const glm::vec3& eye, const glm::vec3& center, float meanRadius);

// Where the representative point chosen last frame is now. `local` is that
// point in the object's own frame, so carrying it through this frame's world
// matrix follows the object's motion and rotation.
struct TrackedPoint {
    glm::vec3 local{0.0f};  // in the object's frame
    glm::vec3 world{0.0f};  // where it was when chosen
    glm::vec3 eye{0.0f};    // the eye it was seen from
    bool valid = false;
};

// Chooses this frame's representative point and remembers it for the next.
TrackedPoint trackPoint(const glm::vec3& eye, const glm::mat4& objectWorld, const glm::vec3& localCenter,
                        float meanRadius);

// Angular speed, in degrees per second, at which last frame's representative
// point moved across the visual field: the angle between the eye-to-point
// vectors p then and p + Δp now, over dt. 0 without a previous frame.
float angularSpeed(const TrackedPoint& previous, const glm::mat4& objectWorldNow, const glm::vec3& eyeNow,
                   float dtSeconds);

}  // namespace arcomp
