#include "graph/CostModel.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>

namespace arcomp {

namespace {
// Prior variances of the fit: the gain is known to about ±0.3 at the start,
// the offset to about ±3 ms; a handful of frames outweighs them.
constexpr double kGainVariance = 0.1;
constexpr double kOffsetVariance = 10.0;
// The cap on the covariance's trace (windup, see RecursiveLeastSquares.hpp).
constexpr double kMaxTrace = 100.0;
// Bounds that keep one wild measurement (a stall of the machine) from
// turning the prediction upside down.
constexpr double kMinGain = 0.25, kMaxGain = 4.0;
} // namespace

CostModel::CostModel(std::size_t levels)
    : levels_(std::max<std::size_t>(levels, 1)), table_(levels_ * kShadingCount), fit_(2, 0.98, 1.0, kMaxTrace) {
    resetFit();
}

std::size_t CostModel::index(std::size_t level, Shading shading) const {
    return std::min(level, levels_ - 1) * kShadingCount + static_cast<std::size_t>(shading);
}

void CostModel::set(std::size_t level, Shading shading, CostCoefficients c) {
    if (level >= levels_) std::abort();
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

double CostModel::itemsMs(const DrawList& list) const {
    double sum = 0.0;
    for (const DrawItem& item : list.items) sum += itemMs(item.level, item.shading, item.screenArea);
    return sum;
}

double CostModel::frameMs(double itemsMs) const { return gain() * itemsMs + offset(); }

void CostModel::observe(double itemsMs, double measuredMs) {
    if (!refit_ || !(measuredMs > 0.0) || !(itemsMs >= 0.0)) return;
    fit_.add(std::array{itemsMs, 1.0}, measuredMs - overheadMs);
}

void CostModel::enableRefit(bool on, double forgetting) {
    refit_ = on;
    fit_ = RecursiveLeastSquares(2, forgetting, 1.0, kMaxTrace);
    resetFit();
}

// The fit is of measured - overheadMs, so that a table loaded or changed
// later needs no reset.
void CostModel::resetFit() { fit_.reset(std::array{1.0, 0.0}, std::array{kGainVariance, kOffsetVariance}); }

double CostModel::gain() const { return refit_ ? std::clamp(fit_.parameters()[0], kMinGain, kMaxGain) : 1.0; }
double CostModel::offset() const { return overheadMs + (refit_ ? fit_.parameters()[1] : 0.0); }

} // namespace arcomp
