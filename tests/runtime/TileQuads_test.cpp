// Occupied tiles as few quads: runs in a row are one quad, rows with the
// same runs are one quad together, partial tiles at the image's edge are
// cut to it, and rows count from the top or the bottom as asked.

#include "runtime/composite/TileQuads.hpp"

#include <gtest/gtest.h>

#include <array>

using namespace arcomp;

namespace {

// A quad's pixel rectangle [x0, x1) x [y0, y1), y from the bottom, from its six NDC vertices.
struct PixelRect {
    float x0, y0, x1, y1;
};
std::vector<PixelRect> rectangles(const std::vector<float>& quads, glm::ivec2 size) {
    std::vector<PixelRect> out;
    for (std::size_t q = 0; q + 12 <= quads.size(); q += 12) {
        PixelRect r{1e9f, 1e9f, -1e9f, -1e9f};
        for (std::size_t v = 0; v < 6; ++v) {
            const float x = (quads[q + 2 * v] + 1.0f) * 0.5f * static_cast<float>(size.x);
            const float y = (quads[q + 2 * v + 1] + 1.0f) * 0.5f * static_cast<float>(size.y);
            r = {std::min(r.x0, x), std::min(r.y0, y), std::max(r.x1, x), std::max(r.y1, y)};
        }
        out.push_back(r);
    }
    return out;
}

TEST(TileQuads, runsAndRowsWithTheSameRunsBecomeOneQuadEach) {
    // 5 x 3 tiles of 8 over 36 x 20 pixels: the last column is 4 wide, the last row 4 high.
    const glm::ivec2 size{36, 20};
    const std::vector<std::uint8_t> occupied = {
        1, 1, 0, 1, 1,  // grid row 0
        1, 1, 0, 1, 1,  // the same runs: merged with row 0
        0, 1, 0, 0, 0,
    };
    std::vector<float> quads{7.0f};  // appended to, not replaced
    const std::size_t pixels = appendTileQuads(occupied, size, 8, TileRows::FromBottom, quads);
    ASSERT_EQ(quads.size(), 1u + 3u * 12u);
    EXPECT_EQ(quads[0], 7.0f);
    quads.erase(quads.begin());
    const std::vector<PixelRect> r = rectangles(quads, size);
    ASSERT_EQ(r.size(), 3u);
    const std::array<PixelRect, 3> expected{{{0, 0, 16, 16}, {24, 0, 36, 16}, {8, 16, 16, 20}}};
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_FLOAT_EQ(r[i].x0, expected[i].x0) << i;
        EXPECT_FLOAT_EQ(r[i].y0, expected[i].y0) << i;
        EXPECT_FLOAT_EQ(r[i].x1, expected[i].x1) << i;
        EXPECT_FLOAT_EQ(r[i].y1, expected[i].y1) << i;
    }
    EXPECT_EQ(pixels, 16u * 16u + 12u * 16u + 8u * 4u);
}

TEST(TileQuads, rowsFromTheTopAreMirroredInY) {
    const glm::ivec2 size{16, 24};
    const std::vector<std::uint8_t> occupied = {1, 0, 0, 0, 0, 0};  // the grid's first row, first tile
    std::vector<float> top, bottom;
    EXPECT_EQ(appendTileQuads(occupied, size, 8, TileRows::FromTop, top), 64u);
    EXPECT_EQ(appendTileQuads(occupied, size, 8, TileRows::FromBottom, bottom), 64u);
    const PixelRect t = rectangles(top, size)[0], b = rectangles(bottom, size)[0];
    EXPECT_FLOAT_EQ(t.y0, 16.0f);  // the image's top rows: window rows 16-23
    EXPECT_FLOAT_EQ(t.y1, 24.0f);
    EXPECT_FLOAT_EQ(b.y0, 0.0f);
    EXPECT_FLOAT_EQ(b.y1, 8.0f);
    EXPECT_FLOAT_EQ(t.x0, b.x0);
}

TEST(TileQuads, noOccupiedTileGivesNoQuad) {
    std::vector<float> quads;
    EXPECT_EQ(appendTileQuads(std::vector<std::uint8_t>(6, 0), {16, 24}, 8, TileRows::FromTop, quads), 0u);
    EXPECT_TRUE(quads.empty());
}

}  // namespace
