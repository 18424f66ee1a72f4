#pragma once
// What a frame will cost, before it is drawn (paper: uniform-frame-time,
// DESIGN.md §3). Each object costs t = A·pixels + B, with A and B measured
// for each (LOD level, shading) pair on the machine at hand; a frame costs
// the sum over what it draws plus a per-frame overhead (clear, read-back,
// compositing) that is measured too.
//
//   CostModel model(3);                                   // three LOD levels
//   model.set(0, Shading::Phong, {.msPerPixel = 2e-5, .ms = 0.9});
//   model.overheadMs = 1.5;
//   double itemsMs = model.itemsMs(list, scene, view);    // calibrated sum
//   double frameMs = model.frameMs(itemsMs);              // with the online fit
//   ... draw, time it ...
//   model.observe(itemsMs, measuredMs);
//
// The calibrated table comes from `arcomp-bench calibrate` (runtime/
// CostCalibration.hpp). While the station runs, observe() re-fits one gain
// on the table's sum by recursive least squares with forgetting, so the
// prediction follows the machine as its load changes; the overhead stays as
// measured. Why one number: a frame's measurement is one number, the sum
// over many objects. While the controller holds the frame time steady, every
// frame feeds nearly the same sum, and a gain and an offset fitted together
// cannot be told apart (one drifts to its bound, the other takes over, and
// the prediction stops responding to what is drawn). A gain alone is
// identified by every frame that draws anything.

#include "graph/budget/RecursiveLeastSquares.hpp"
#include "graph/core/DrawList.hpp"
#include "graph/core/Scene.hpp"
#include "graph/core/View.hpp"

#include <vector>

namespace arcomp {

// A and B of the paper's cost formula for one (level, shading) pair.
struct CostCoefficients {
    double msPerPixel = 0.0;  // A
    double ms = 0.0;          // B
};

class CostModel {
public:
    // levels ≥ 1; every entry starts at zero cost. Levels beyond the last
    // cost what the last one costs.
    explicit CostModel(std::size_t levels = 1);

    std::size_t levels() const { return levels_; }
    void set(std::size_t level, Shading shading, CostCoefficients c);
    const CostCoefficients& at(std::size_t level, Shading shading) const;

    // The calibrated cost of one object, without the online fit; `pixels`
    // are those it covers on screen (graph/budget/OnScreenPixels.hpp).
    double itemMs(std::size_t level, Shading shading, double pixels) const;
    // The calibrated cost of everything in the list, seen from `view`,
    // without the overhead.
    double itemsMs(const DrawList& list, const Scene& scene, const View& view) const;
    // Predicted frame time for objects whose calibrated costs sum to itemsMs:
    // gain · itemsMs + overheadMs; before any observation the gain is 1.
    double frameMs(double itemsMs) const;

    // Online re-fitting: the calibrated sum that was predicted and the frame
    // time measured for it. `forgetting` is λ per frame (0.25: the last
    // frame weighs three quarters). The table's error comes from the view
    // (occlusion, overdraw, how well a bounding sphere stands for the pixels
    // drawn) and from the mix of levels and shadings drawn, and it drifts
    // along a camera path: in `arcomp-bench budget` one frame's error predicts the
    // next's with correlation 0.98, so a short memory predicts best. With
    // λ = 0.6 against 0.25, interleaved runs on this 2-core host (nothing
    // else running), p95 |dev| from the target was 13.7-21.9% against
    // 9.4-10.9% in one hour, 12.5-20.3% against 13.2-17.8% in a noisier
    // one; frames over the target by 20%: 1.5-4.7% against 1.3-1.8%, then
    // 0.5-3.0% against 1.3% each. What is left is mostly the table's error
    // changing from one mix of levels and shadings to the next.
    // Frames that draw (almost) nothing say nothing about the gain and are
    // ignored. Once kSettlingFrames frames have been fitted, each frame's
    // own gain enters the fit within a factor kMaxSampleRatio of the
    // current gain, so a stall of the machine (a frame ten times as long)
    // moves the prediction by a bounded step that the next frames undo.
    // Before that the clamp only slowed the start: the managed flight
    // needed a gain of 1.8-2.5 from its first frame (a table fitted with A
    // per shading and B per level under-predicted the controller's coarse,
    // unlit mixes; graph/budget/CostTableFit.hpp), and at 1.25× per frame
    // its first 3-5 frames ran 25-130% over the target.
    // Letting single stalls pass unheeded, by fitting the median of the last
    // three or five frames' gains, was tried: the view's own changes of
    // cost then reach the gain a frame or two late.
    void observe(double itemsMs, double measuredMs);
    void enableRefit(bool on, double forgetting = kDefaultForgetting);
    // Forgets the fit: gain 1.
    void resetFit();
    double gain() const;
    // The per-frame time that does not scale with what is drawn: overheadMs.
    double offset() const { return overheadMs; }

    static constexpr double kDefaultForgetting = 0.25;
    static constexpr double kMaxSampleRatio = 1.25;
    static constexpr std::size_t kSettlingFrames = 3;

    double overheadMs = 0.0;

private:
    std::size_t index(std::size_t level, Shading shading) const;

    std::size_t levels_;
    std::vector<CostCoefficients> table_;  // level-major, kShadingCount per level
    bool refit_ = true;
    RecursiveLeastSquares fit_;
};

}  // namespace arcomp
