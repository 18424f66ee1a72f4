#pragma once
// The station config's `budget` section: the frame-time controller
// (graph/budget/FrameBudget.hpp) on or off, its target, what it may change and the
// calibration it predicts from. Documented in configs/README.md.
//
//   budget:
//     enabled: true
//     target_ms: 33.3
//     calibration: station.calibration.yaml   # from `arcomp-bench calibrate`
//
//   BudgetConfig b;  readBudgetConfig(root, b);      // errors go to root's report
//   if (b.enabled) FrameBudget budget(readCalibration(b.calibration), toBudgetSettings(b));
//
// An absent section leaves the controller off: objects are drawn as the
// select pass chose them, as before.

#include "graph/budget/FrameBudget.hpp"
#include "runtime/config/YamlMap.hpp"

#include <filesystem>

namespace arcomp {

// Defaults are the controller's own.
struct BudgetConfig {
    bool enabled = false;
    double targetMs = BudgetSettings{}.targetMs;
    bool changeLevel = BudgetSettings{}.changeLevel;
    bool changeShading = BudgetSettings{}.changeShading;
    std::filesystem::path calibration;
    bool refit = true;                                                 // re-fit the cost model while running
    double upgradeMarginPct = 100.0 * BudgetSettings{}.upgradeMargin;  // hysteresis band below the target
    int holdFrames = BudgetSettings{}.holdFrames;
    float eccentricityFloor = BudgetSettings{}.eccentricityFloor;  // 1: importance by screen size alone
};

void readBudgetConfig(YamlMap& root, BudgetConfig& out);
BudgetSettings toBudgetSettings(const BudgetConfig& config);

}  // namespace arcomp
