#pragma once
// A deterministic CPU coverage rasterizer: which pixels a triangle list
// covers, with no depth and no culling. It is the silhouette proof's judge,
// so it needs no GL and gives the same answer on every machine: vertices
// snap to 1/256 pixel, edge functions are exact 64-bit integers, samples sit
// at pixel centres and the top-left rule gives a pixel on an edge shared by
// two triangles to exactly one of them.
//
//   CoverageMask mask(512, 512);
//   rasterizeCoverage(positions, indices, view.viewProjection(), mask);
//   MaskDifference d = compareMasks(fullMask, mask);

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace arcomp {

struct CoverageMask {
    int width = 0, height = 0;
    std::vector<std::uint8_t> pixels;  // row-major, row 0 at the top; 1 = covered

    CoverageMask() = default;
    CoverageMask(int w, int h) : width(w), height(h), pixels(static_cast<std::size_t>(w) * h, 0) {}
    std::uint8_t at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
    std::size_t covered() const;
    void clear() { std::fill(pixels.begin(), pixels.end(), 0); }
};

// Adds the triangles' coverage to `mask`. Returns how many triangles were
// skipped because a vertex lies behind the eye (w <= 0) or absurdly far off
// screen; callers that need every triangle treat nonzero as an error.
std::size_t rasterizeCoverage(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
                              const glm::mat4& viewProjection, CoverageMask& mask);

struct MaskDifference {
    std::size_t differing = 0;
    // Differing pixels with no pixel of the reference's outline (a covered
    // pixel next to an uncovered one, either side) within one pixel.
    std::size_t differingFarFromOutline = 0;
};

MaskDifference compareMasks(const CoverageMask& reference, const CoverageMask& other);

}  // namespace arcomp
