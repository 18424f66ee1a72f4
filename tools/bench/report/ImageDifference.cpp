#include "tools/bench/report/ImageDifference.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace arcomp {

double psnr(const Image& reference, const Image& test) {
    if (reference.width != test.width || reference.height != test.height || reference.rgba.size() != test.rgba.size())
        throw std::invalid_argument("psnr: images differ in size");
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < reference.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        const double d = double(reference.rgba[i]) - double(test.rgba[i]);
        sum += d * d;
        ++count;
    }
    if (count == 0 || sum == 0.0) return std::numeric_limits<double>::infinity();
    const double mse = sum / double(count);
    return 10.0 * std::log10(255.0 * 255.0 / mse);
}

}  // namespace arcomp
