#include "graph/silhouette/CoverageRaster.hpp"

#include <gtest/gtest.h>

using namespace arcomp;

namespace {
// Identity view-projection: positions are NDC, so x, y in [-1, 1] fill the mask.
const glm::mat4 kIdentity(1.0f);
}  // namespace

TEST(CoverageRaster, fullScreenQuadCoversEveryPixel) {
    const std::vector<glm::vec3> p = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    const std::vector<std::uint32_t> idx = {0, 1, 2, 0, 2, 3};
    CoverageMask m(64, 48);
    EXPECT_EQ(rasterizeCoverage(p, idx, kIdentity, m), 0u);
    EXPECT_EQ(m.covered(), 64u * 48u);
}

TEST(CoverageRaster, sharedEdgeThroughPixelCentresGoesToExactlyOneTriangle) {
    // A square whose diagonal runs exactly through pixel centres of an 8x8 mask.
    const std::vector<glm::vec3> p = {
        {-0.875f, -0.875f, 0}, {0.875f, -0.875f, 0}, {0.875f, 0.875f, 0}, {-0.875f, 0.875f, 0}};
    const std::vector<std::uint32_t> first = {0, 1, 2}, second = {0, 2, 3}, both = {0, 1, 2, 0, 2, 3};
    CoverageMask a(8, 8), b(8, 8), ab(8, 8);
    rasterizeCoverage(p, first, kIdentity, a);
    rasterizeCoverage(p, second, kIdentity, b);
    rasterizeCoverage(p, both, kIdentity, ab);
    std::size_t overlap = 0;
    for (std::size_t i = 0; i < ab.pixels.size(); ++i) overlap += a.pixels[i] & b.pixels[i];
    EXPECT_EQ(overlap, 0u);
    EXPECT_EQ(a.covered() + b.covered(), ab.covered());
    EXPECT_EQ(ab.covered(), 7u * 7u);  // centres at -0.875 .. 0.625 in NDC; the far edges are not owned
}

TEST(CoverageRaster, windingDoesNotMatter) {
    const std::vector<glm::vec3> p = {{-0.5f, -0.5f, 0}, {0.5f, -0.5f, 0}, {0, 0.5f, 0}};
    CoverageMask ccw(32, 32), cw(32, 32);
    rasterizeCoverage(p, std::vector<std::uint32_t>{0, 1, 2}, kIdentity, ccw);
    rasterizeCoverage(p, std::vector<std::uint32_t>{0, 2, 1}, kIdentity, cw);
    EXPECT_GT(ccw.covered(), 0u);
    EXPECT_EQ(ccw.pixels, cw.pixels);
}

TEST(CoverageRaster, compareMasksSeparatesOutlineFromInterior) {
    CoverageMask ref(10, 10), other(10, 10);
    for (int y = 2; y < 8; ++y)
        for (int x = 2; x < 8; ++x) ref.pixels[y * 10 + x] = other.pixels[y * 10 + x] = 1;
    other.pixels[2 * 10 + 2] = 0;  // on the outline
    other.pixels[5 * 10 + 5] = 0;  // two pixels inside it
    const MaskDifference d = compareMasks(ref, other);
    EXPECT_EQ(d.differing, 2u);
    EXPECT_EQ(d.differingFarFromOutline, 1u);
}
