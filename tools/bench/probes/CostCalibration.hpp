#pragma once
// Measures the cost model's A and B (t = A·pixels + B, paper:
// uniform-frame-time) for every (LOD level, shading) pair of one object on
// the machine at hand, and the per-frame overhead: the object's level meshes
// are drawn alone, at several sizes on screen, and timed.
//
//   RenderTarget target({1280, 720});  target.bind();
//   Renderer renderer;  FrameTimer timer;
//   CostModel model = calibrateCosts(scene, levelMeshes, renderer, timer, {.viewport = {1280, 720}});
//   writeCalibration("station.calibration.yaml", model, {glDescription(), {1280, 720}});
//
// `pixels` are what the controller charges (graph/budget/OnScreenPixels.hpp):
// the projected disc of the bounding sphere, less what falls off screen, so
// the fit maps that very number to time. A frame's overhead is the time of a
// frame that draws nothing.

#include "graph/budget/CostModel.hpp"
#include "graph/core/Scene.hpp"
#include "runtime/gl/FrameTimer.hpp"
#include "runtime/render/Renderer.hpp"

#include <optional>
#include <span>
#include <vector>

namespace arcomp {

struct CalibrationOptions {
    glm::ivec2 viewport{1280, 720};
    // Sizes on screen: projected disc area as a fraction of the viewport.
    std::vector<float> screenFractions{0.01f, 0.05f, 0.15f, 0.35f, 0.7f};
    int repeats = 5;  // the median of this many frames per sample
    // Direction the object is seen from (towards the eye); a flight looks down.
    glm::vec3 viewDirection = glm::normalize(glm::vec3(0.0f, 0.5f, 1.0f));
    std::optional<glm::vec4> clearColor = glm::vec4(0.5f, 0.6f, 0.8f, 1.0f);
};

// levelMeshes: the object's mesh node per level, finest first (all under the
// same world matrix). The render target must be bound and sized
// options.viewport. The result has levelMeshes.size() levels.
CostModel calibrateCosts(const Scene& scene, std::span<const NodeId> levelMeshes, Renderer& renderer, FrameTimer& timer,
                         const CalibrationOptions& options);

// Sharpens a table with whole frames of the station's own scene, so that
// objects hiding one another, overdraw and the real mix of meshes are in
// the fit: each of `frames` samples takes one of `lists` (a select pass's
// output, drawn from views[i]), draws a random mix of levels and of
// shadings for the frame, puts each item at a setting drawn from that mix,
// and times it; then `prior` is scaled to fit all the frames at once, each
// shading's A by a gain of its own and every B by one
// (graph/budget/CostTableFit.hpp). The overhead is kept from `prior`.
CostModel fitCostsOnFrames(const Scene& scene, std::span<const DrawList> lists, std::span<const View> views,
                           Renderer& renderer, FrameTimer& timer, const CostModel& prior, int frames,
                           const CalibrationOptions& options, unsigned seed = 1);

}  // namespace arcomp
