#pragma once
// One station frame in numbers: each stage's milliseconds and the counters
// an operator watches (runtime/operator/StationMetrics.hpp serves them). CPU stages
// are this frame's wall time. GL stages are the previous frame's, from
// runtime/gl/GpuStageTimes.hpp: read one frame late so that timing never
// stalls a GPU (on a software rasterizer, the stage's wall time, waited for).

#include "graph/budget/FrameBudget.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>

namespace arcomp {

struct FrameStats {
    std::uint64_t frame = 0;  // frames composited so far, this one included
    double captureMs = 0;     // CPU: wait for / decode the frame
    double matteMs = 0;       // CPU: person layer
    double trackMs = 0;       // CPU: people tracked, and their depths with a calibrated camera
    double peopleMs = 0;      // CPU: the people placed on the floor (runtime/people) and sent to show control
    double updateMs = 0;      // CPU: transforms and bounds
    double selectMs = 0;      // CPU: culling, LOD, grouping cut, silhouette region, bins
    double budgetMs = 0;      // CPU: the frame-time controller (0 when it is off)
    double shadowMs = 0;      // GL: contact shadows on the video's floor (0 without)
    double renderMs = 0;      // GL: CG, all objects, shaded (what the controller observes)
    double pointCloudMs = 0;  // CPU: point clouds splatted and laid over the CG (0 without)
    double holdoutMs = 0;     // GL: holdout mask from the front objects' silhouette meshes
    double compositeMs = 0;   // GL: backdrop upload, person upload and tiles
    double outputMs = 0;      // CPU: read back and write files (0 without file outputs)
    // From the frame's capture (the input handing it over) to its people's
    // last datagram leaving for show control; 0 without show control.
    double captureToPeopleSentMs = 0;
    double totalMs = 0;  // wall time of the whole frame on the CPU
    std::size_t cgTriangles = 0;
    std::size_t holdoutTriangles = 0;
    std::size_t objectsInFront = 0;
    std::size_t objectsBehind = 0;
    std::size_t personTiles = 0;  // Compositor::kTile-square tiles where the matte had any alpha
    std::size_t people = 0;       // tracked people with a depth of their own
    // The controller's view of the CG render stage, when it is on: its target
    // (the frame target less what the other stages took last frame), its
    // prediction, and the area-weighted quality it kept (1 = finest).
    std::optional<BudgetStats> budget;
    bool newVideoFrame = false;  // live: false when the camera had nothing new
};

}  // namespace arcomp
