#pragma once
// The frame-time controller (paper: uniform-frame-time, DESIGN.md §3): after
// the select pass, it lowers or raises each drawn object's LOD level and
// shading so that the predicted frame time meets the target while quality
// stays as high as that allows. One call between select and render, one
// after the frame is timed:
//
//   FrameBudget budget(model, {.targetMs = 33.3});
//   select(scene, view, settings, list);
//   BudgetStats s = budget.apply(scene, list, view, gaze);   // edits list
//   renderer.draw(scene, list, view);  ... time it ...
//   budget.observe(measuredMs);        // re-fits the cost model
//
// The paper's algorithm, on objects ordered by importance: when the
// prediction is over the target, the least important object's shading goes
// down one step, at the lowest shading its level goes down one and shading
// back to the highest, and when both are lowest the next object follows.
// With time to spare, from the most important object down, shading goes up,
// then level, keeping the last setting that fits.
//
// Beyond the paper:
// - Importance is screen area weighted by eccentricity acuity k1 (graph/
//   GazeAcuity.hpp) of the angle from the gaze, or from the screen centre
//   when no gaze is given: the paper named position on screen as missing.
// - History (the paper's second open item): each object's setting carries
//   over from the last frame; raising must fit under the target less a
//   margin (a band where nothing changes), and an object just lowered is not
//   raised again for holdFrames frames. An object that does not fit its next
//   step is skipped, so smaller ones can use what time is left.
// - The select pass's level and shading are the finest the controller uses:
//   an LOD policy's judgement that more detail is wasted still holds.
// - O(n log n) a frame: one sort; every step is O(1).

#include "graph/budget/CostModel.hpp"
#include "graph/core/View.hpp"
#include "graph/lod/GazeAcuity.hpp"
#include "graph/lod/LodAlternatives.hpp"

#include <vector>

namespace arcomp {

struct BudgetSettings {
    double targetMs = 1000.0 / 30.0;
    bool changeLevel = true;
    bool changeShading = true;
    // Raising a setting must leave this fraction of the target unused.
    double upgradeMargin = 0.02;
    // Frames an object stays down after being lowered before it may rise.
    int holdFrames = 4;
    // Importance = screen area · (floor + (1 - floor) · k1(θ)); 1 ranks by
    // screen size alone, as the paper did.
    float eccentricityFloor = 0.25f;
    GazeAcuityParams acuity{};  // a and c1 of k1
};

// What the controller did to one frame, for a stats overlay or a log.
struct BudgetStats {
    double targetMs = 0.0;
    double predictedMs = 0.0;          // this frame, after the edits, with the online fit
    double measuredMs = 0.0;           // the last frame observed; 0 before any
    double measuredPredictedMs = 0.0;  // what had been predicted for that frame
    double quality = 1.0;              // screen-area-weighted, 1: all at the finest allowed
    std::size_t stepsDown = 0, stepsUp = 0;
    std::size_t itemsReduced = 0;  // items below the finest allowed
};

class FrameBudget {
public:
    explicit FrameBudget(CostModel model, BudgetSettings settings = {});

    // Edits level, shading, node and part of the list's items. `gaze` is a
    // world-space direction; zero takes the view's forward (screen centre).
    BudgetStats apply(const Scene& scene, DrawList& list, const View& view, glm::vec3 gaze = glm::vec3(0.0f));
    // The measured time of the frame last passed to apply().
    void observe(double measuredMs);

    const BudgetStats& stats() const { return stats_; }
    const CostModel& model() const { return model_; }
    CostModel& model() { return model_; }
    const BudgetSettings& settings() const { return settings_; }
    void setTarget(double ms) { settings_.targetMs = ms; }
    // Forgets every object's history (after a cut in a replay).
    void reset();

private:
    struct Work {
        std::uint32_t item;
        NodeId object;
        float importance;
        std::uint8_t step, maxStep;  // steps below the finest allowed
        std::uint8_t topLevel, shadingSpan, topShading;
        double cost;  // calibrated ms at `step`
    };
    std::uint8_t levelAt(const Work& w, int step) const;
    Shading shadingAt(const Work& w, int step) const;
    double costAt(const Work& w, int step, float pixels) const;
    void ensureState(const Scene& scene);

    CostModel model_;
    BudgetSettings settings_;
    BudgetStats stats_;
    LodAlternatives alternatives_;
    const Scene* scene_ = nullptr;
    std::vector<Work> work_;
    std::vector<std::uint32_t> order_;
    std::vector<float> pixels_;
    // Per object (level 0's mesh node), flat: its step, and the frame (+1)
    // it was last drawn and last lowered; 0 means never.
    std::vector<std::uint8_t> step_;
    std::vector<std::uint32_t> seen_, lowered_;
    std::uint32_t frame_ = 0;
    double lastItemsMs_ = 0.0;
    double lastPredictedMs_ = 0.0;
};

}  // namespace arcomp
