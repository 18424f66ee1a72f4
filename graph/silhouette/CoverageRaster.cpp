#include "graph/silhouette/CoverageRaster.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace arcomp {

namespace {

constexpr int kSubBits = 8;
constexpr std::int64_t kSub = 1 << kSubBits;
constexpr double kMaxPixels = 1 << 20;  // keeps edge products far inside 64 bits

struct Fixed {
    std::int64_t x, y;
};

// The inward normal of edge a->b is (-(b.y-a.y), b.x-a.x); the edge owns
// samples on it when that normal points right, or straight down (y grows
// downwards): the top-left rule for this orientation.
bool ownsSamplesOnEdge(Fixed a, Fixed b) {
    const std::int64_t nx = -(b.y - a.y), ny = b.x - a.x;
    return nx > 0 || (nx == 0 && ny > 0);
}

}  // namespace

std::size_t CoverageMask::covered() const {
    return static_cast<std::size_t>(std::count(pixels.begin(), pixels.end(), std::uint8_t{1}));
}

std::size_t rasterizeCoverage(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
                              const glm::mat4& viewProjection, CoverageMask& mask) {
    std::size_t skipped = 0;
    std::vector<Fixed> screen(positions.size());
    std::vector<char> usable(positions.size(), 1);
    for (std::size_t v = 0; v < positions.size(); ++v) {
        const glm::vec4 c = viewProjection * glm::vec4(positions[v], 1.0f);
        if (!(c.w > 1e-12f)) {
            usable[v] = 0;
            continue;
        }
        const double px = (double(c.x) / c.w * 0.5 + 0.5) * mask.width;
        const double py = (0.5 - double(c.y) / c.w * 0.5) * mask.height;
        if (!(std::abs(px) < kMaxPixels && std::abs(py) < kMaxPixels)) {
            usable[v] = 0;
            continue;
        }
        screen[v] = {std::llround(px * kSub), std::llround(py * kSub)};
    }
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const std::uint32_t i0 = indices[t], i1 = indices[t + 1], i2 = indices[t + 2];
        if (!usable[i0] || !usable[i1] || !usable[i2]) {
            ++skipped;
            continue;
        }
        Fixed p[3] = {screen[i0], screen[i1], screen[i2]};
        const std::int64_t area = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[1].y - p[0].y) * (p[2].x - p[0].x);
        if (area == 0) continue;
        if (area < 0) std::swap(p[1], p[2]);
        const std::int64_t minX = std::min({p[0].x, p[1].x, p[2].x}), maxX = std::max({p[0].x, p[1].x, p[2].x});
        const std::int64_t minY = std::min({p[0].y, p[1].y, p[2].y}), maxY = std::max({p[0].y, p[1].y, p[2].y});
        // Pixels whose centre (x + 0.5) can lie in [min, max].
        const int x0 = static_cast<int>(std::max<std::int64_t>(0, (minX - kSub / 2 + kSub - 1) >> kSubBits));
        const int x1 = static_cast<int>(std::min<std::int64_t>(mask.width - 1, (maxX - kSub / 2) >> kSubBits));
        const int y0 = static_cast<int>(std::max<std::int64_t>(0, (minY - kSub / 2 + kSub - 1) >> kSubBits));
        const int y1 = static_cast<int>(std::min<std::int64_t>(mask.height - 1, (maxY - kSub / 2) >> kSubBits));
        if (x0 > x1 || y0 > y1) continue;
        std::int64_t dx[3], dy[3], bias[3], rowStart[3];
        const std::int64_t sx = std::int64_t{x0} * kSub + kSub / 2, sy = std::int64_t{y0} * kSub + kSub / 2;
        for (int e = 0; e < 3; ++e) {
            const Fixed a = p[e], b = p[(e + 1) % 3];
            // E(s) = (b.x-a.x)(s.y-a.y) - (b.y-a.y)(s.x-a.x) > 0 inside.
            dx[e] = -(b.y - a.y) * kSub;  // change per pixel step in x
            dy[e] = (b.x - a.x) * kSub;   // change per pixel step in y
            bias[e] = ownsSamplesOnEdge(a, b) ? 0 : -1;
            rowStart[e] = (b.x - a.x) * (sy - a.y) - (b.y - a.y) * (sx - a.x);
        }
        for (int y = y0; y <= y1; ++y) {
            std::int64_t w0 = rowStart[0], w1 = rowStart[1], w2 = rowStart[2];
            std::uint8_t* row = &mask.pixels[static_cast<std::size_t>(y) * mask.width];
            for (int x = x0; x <= x1; ++x) {
                if ((w0 + bias[0]) >= 0 && (w1 + bias[1]) >= 0 && (w2 + bias[2]) >= 0) row[x] = 1;
                w0 += dx[0];
                w1 += dx[1];
                w2 += dx[2];
            }
            for (int e = 0; e < 3; ++e) rowStart[e] += dy[e];
        }
    }
    return skipped;
}

MaskDifference compareMasks(const CoverageMask& reference, const CoverageMask& other) {
    if (reference.width != other.width || reference.height != other.height)
        throw std::invalid_argument("compareMasks: masks differ in size");
    const int w = reference.width, h = reference.height;
    auto outline = [&](int x, int y) {
        const std::uint8_t v = reference.at(x, y);
        for (int j = std::max(0, y - 1); j <= std::min(h - 1, y + 1); ++j)
            for (int i = std::max(0, x - 1); i <= std::min(w - 1, x + 1); ++i)
                if (reference.at(i, j) != v) return true;
        return false;
    };
    MaskDifference d;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (reference.at(x, y) == other.at(x, y)) continue;
            ++d.differing;
            bool nearOutline = false;
            for (int j = std::max(0, y - 1); j <= std::min(h - 1, y + 1) && !nearOutline; ++j)
                for (int i = std::max(0, x - 1); i <= std::min(w - 1, x + 1) && !nearOutline; ++i)
                    nearOutline = outline(i, j);
            if (!nearOutline) ++d.differingFarFromOutline;
        }
    return d;
}

}  // namespace arcomp
