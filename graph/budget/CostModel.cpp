#include "graph/budget/CostModel.hpp"
#include "graph/budget/OnScreenPixels.hpp"
#include "graph/core/Check.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>

namespace arcomp {

namespace {
// The fit averages each frame's own gain, weighted by how much of the frame
// the items are (a frame that is mostly overhead says little about them),
// so the variances are in units of one fully weighted frame's: the prior
// counts as two frames, and the covariance can never wind up past one
// frame's worth however long the weights stay small.
constexpr double kGainVariance = 0.5;
constexpr double kMaxVariance = 1.0;
// Bounds on the gain: a table off by more than this is the wrong table.
constexpr double kMinGain = 0.25, kMaxGain = 4.0;
// Frames whose calibrated items cost less than this draw too little to
// tell anything about the gain (an empty view is all overhead).
constexpr double kMinItemsMs = 0.05;
}  // namespace

CostModel::CostModel(std::size_t levels)
    : levels_(std::max<std::size_t>(levels, 1)), table_(levels_ * kShadingCount),
      fit_(1, kDefaultForgetting, kGainVariance, kMaxVariance) {
    resetFit();
}

std::size_t CostModel::index(std::size_t level, Shading shading) const {
    return std::min(level, levels_ - 1) * kShadingCount + static_cast<std::size_t>(shading);
}

void CostModel::set(std::size_t level, Shading shading, CostCoefficients c) {
    ARCOMP_CHECK(level < levels_, "a level the model was made for");
    table_[index(level, shading)] = c;
}

const CostCoefficients& CostModel::at(std::size_t level, Shading shading) const {
    return table_[index(level, shading)];
}

// Paper: uniform-frame-time, section 2: object time = A_x · pixels + B_x,
// A_x and B_x per level of detail and shading algorithm.
double CostModel::itemMs(std::size_t level, Shading shading, double pixels) const {
    const CostCoefficients& c = at(level, shading);
    return c.msPerPixel * pixels + c.ms;
}

double CostModel::itemsMs(const DrawList& list, const Scene& scene, const View& view) const {
    double sum = 0.0;
    for (const DrawItem& item : list.items) sum += itemMs(item.level, item.shading, onScreenPixels(item, scene, view));
    return sum;
}

double CostModel::frameMs(double itemsMs) const { return gain() * itemsMs + overheadMs; }

// Fits measured - overheadMs ≈ gain · itemsMs, so that a table loaded or
// changed later needs no reset.
void CostModel::observe(double itemsMs, double measuredMs) {
    if (!refit_ || !std::isfinite(measuredMs) || !std::isfinite(itemsMs) || itemsMs < kMinItemsMs) return;
    // The frame's own gain, (measured - overhead) / items, kept within the
    // bounds and, once the fit has settled, within a factor kMaxSampleRatio
    // of the current gain. Before that there is no steady gain for a stall
    // to stand out from.
    const double current = gain();
    const bool settled = fit_.samples() >= kSettlingFrames;
    const double low = settled ? std::max(kMinGain, current / kMaxSampleRatio) : kMinGain;
    const double high = settled ? std::min(kMaxGain, current * kMaxSampleRatio) : kMaxGain;
    const double sample = std::clamp((measuredMs - overheadMs) / itemsMs, low, high);
    const double weight = std::sqrt(itemsMs / (itemsMs + std::max(overheadMs, 0.0)));
    fit_.add(std::array{weight}, weight * sample);
}

void CostModel::enableRefit(bool on, double forgetting) {
    refit_ = on;
    fit_ = RecursiveLeastSquares(1, forgetting, kGainVariance, kMaxVariance);
    resetFit();
}

void CostModel::resetFit() { fit_.reset(std::array{1.0}, std::array{kGainVariance}); }

double CostModel::gain() const { return refit_ ? std::clamp(fit_.parameters()[0], kMinGain, kMaxGain) : 1.0; }

}  // namespace arcomp
