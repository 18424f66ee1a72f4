#include "tools/bench/report/Stats.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace arcomp {

double percentile(std::span<const double> samples, double p) {
    if (!(p >= 0.0 && p <= 100.0))
        throw std::invalid_argument("percentile: p must lie in 0..100, not " + std::to_string(p));
    if (samples.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::vector<double> v(samples.begin(), samples.end());
    std::sort(v.begin(), v.end());
    const double at = p / 100.0 * static_cast<double>(v.size() - 1);
    const auto lo = static_cast<std::size_t>(std::floor(at));
    const std::size_t hi = std::min(lo + 1, v.size() - 1);
    const double below = v[lo], above = v[hi];
    return below + (above - below) * (at - static_cast<double>(lo));
}

double median(std::span<const double> samples) { return percentile(samples, 50.0); }

}  // namespace arcomp
