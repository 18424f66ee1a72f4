#include "graph/budget/CostTableFit.hpp"

#include <algorithm>
#include <cmath>

namespace arcomp {

namespace {

constexpr std::size_t kFixedGain = kShadingCount;  // θ's last entry
// The gains start at 1, the table as measured, with a prior as wide as
// they are: a few frames move them, a frame's noise does not.
constexpr double kTableGainVariance = 1.0;

}  // namespace

CostTableFit::CostTableFit(const CostModel& singleObject)
    : singleObject_(singleObject), fit_(kShadingCount + 1, 1.0, kTableGainVariance, 1e12), x_(kShadingCount + 1) {
    const std::vector<double> ones(kShadingCount + 1, 1.0), variance(kShadingCount + 1, kTableGainVariance);
    fit_.reset(ones, variance);
}

void CostTableFit::addFrame(std::span<const ChargedItem> items, double itemsMs) {
    std::fill(x_.begin(), x_.end(), 0.0);
    for (const ChargedItem& item : items) {
        const CostCoefficients& c = singleObject_.at(item.level, item.shading);
        x_[static_cast<std::size_t>(item.shading)] += c.msPerPixel * item.pixels;
        x_[kFixedGain] += c.ms;
    }
    // A frame the timer could not measure, or pixels that are not a number,
    // would leave every gain NaN: the frame says nothing, as in observe().
    if (!std::isfinite(itemsMs) || !std::all_of(x_.begin(), x_.end(), [](double v) { return std::isfinite(v); }))
        return;
    fit_.add(x_, itemsMs);
}

CostModel CostTableFit::table() const {
    CostModel model = singleObject_;
    const double fixed = std::max(0.0, gains()[kFixedGain]);
    for (std::size_t level = 0; level < model.levels(); ++level)
        for (int s = 0; s < kShadingCount; ++s) {
            const auto shading = static_cast<Shading>(s);
            const CostCoefficients& c = singleObject_.at(level, shading);
            model.set(level, shading,
                      {std::max(0.0, gains()[static_cast<std::size_t>(s)]) * c.msPerPixel, fixed * c.ms});
        }
    model.resetFit();
    return model;
}

}  // namespace arcomp
