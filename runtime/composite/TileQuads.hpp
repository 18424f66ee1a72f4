#pragma once
// The occupied tiles of a grid over an image as few quads, for a pass that
// draws only there: a run of occupied tiles in a row is one quad, and rows
// with the same runs are one quad together. llvmpipe sets up every
// triangle, and thin ones cost more to set up than to fill.
//
//   std::vector<float> quads;
//   const std::size_t pixels = appendTileQuads(occupied, size, 8, TileRows::FromTop, quads);
//   glDrawArrays(GL_TRIANGLES, 0, quads.size() / 2);

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace arcomp {

// Whether the grid's first row is the image's top (video rows) or its
// bottom (GL window rows).
enum class TileRows { FromTop, FromBottom };

// The grid's tiles across and down: ceil(size / tile), the last ones partial.
inline glm::ivec2 tileGrid(glm::ivec2 size, int tile) { return (size + tile - 1) / tile; }

// `occupied`: per tile, row by row, tileGrid(size, tile) tiles each way; the
// last row and column may be partial. Appends two triangles a quad, NDC x
// and y, to `quads`; returns the pixels they cover.
std::size_t appendTileQuads(const std::vector<std::uint8_t>& occupied, glm::ivec2 size, int tile, TileRows rows,
                            std::vector<float>& quads);

}  // namespace arcomp
