#pragma once
// The frame-time controller (graph/budget/FrameBudget.hpp) as a station
// stage. It steers the CG draw only: before it plans this frame's draw list
// it learns from the previous frame's CG draw, and it plans within what the
// rest of the previous frame left of the config's target.
//
//   BudgetStage budget(cfg.budget);       // reads the calibration; throws
//   // each frame, after select, with `stats` still the previous frame's
//   // but renderMs already its CG draw (GpuStageTimes, read one frame late):
//   stats.budget = budget.plan(scene, list, view, gaze, stats);

#include "graph/budget/FrameBudget.hpp"
#include "runtime/config/BudgetConfig.hpp"
#include "runtime/station/FrameStats.hpp"

namespace arcomp {

class BudgetStage {
public:
    explicit BudgetStage(const BudgetConfig& config);

    BudgetStats plan(const Scene& scene, DrawList& list, const View& view, const glm::vec3& gaze,
                     const FrameStats& previous);

private:
    double targetMs_;
    FrameBudget budget_;
};

}  // namespace arcomp
