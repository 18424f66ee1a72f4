#include "runtime/station/BudgetStage.hpp"

#include "runtime/config/CalibrationFile.hpp"

#include <algorithm>

namespace arcomp {

BudgetStage::BudgetStage(const BudgetConfig& config)
    : targetMs_(config.targetMs), budget_(readCalibration(config.calibration), toBudgetSettings(config)) {
    budget_.model().enableRefit(config.refit);
}

BudgetStats BudgetStage::plan(const Scene& scene, DrawList& list, const View& view, const glm::vec3& gaze,
                              const FrameStats& previous) {
    if (previous.frame > 0) {
        budget_.observe(previous.renderMs);
        const double others = previous.totalMs - previous.renderMs - previous.budgetMs;
        budget_.setTarget(std::max(1.0, targetMs_ - std::max(0.0, others)));
    } else {
        budget_.setTarget(std::max(1.0, targetMs_));
    }
    return budget_.apply(scene, list, view, gaze);
}

}  // namespace arcomp
