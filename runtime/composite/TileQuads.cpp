#include "runtime/composite/TileQuads.hpp"

#include <algorithm>

namespace arcomp {

std::size_t appendTileQuads(const std::vector<std::uint8_t>& occupied, glm::ivec2 size, int tile, TileRows rows,
                            std::vector<float>& quads) {
    const glm::ivec2 grid = tileGrid(size, tile);
    const int tx = grid.x, ty = grid.y;
    const auto ndcX = [&](int x) { return 2.0f * static_cast<float>(x) / static_cast<float>(size.x) - 1.0f; };
    const auto ndcY = [&](int y) {
        const float fromBottom = 2.0f * static_cast<float>(y) / static_cast<float>(size.y) - 1.0f;
        return rows == TileRows::FromBottom ? fromBottom : -fromBottom;
    };
    std::size_t pixels = 0;
    std::vector<glm::ivec2> runs, blockRuns;  // tile columns [x, y)
    int blockFrom = 0;
    const auto closeBlock = [&](int rowEnd) {
        const int y0 = blockFrom * tile, y1 = std::min(size.y, rowEnd * tile);
        for (const glm::ivec2 run : blockRuns) {
            const int x0 = run.x * tile, x1 = std::min(size.x, run.y * tile);
            const float l = ndcX(x0), r = ndcX(x1), b = ndcY(y0), t = ndcY(y1);
            quads.insert(quads.end(), {l, b, r, b, r, t, l, b, r, t, l, t});
            pixels += static_cast<std::size_t>(x1 - x0) * static_cast<std::size_t>(y1 - y0);
        }
    };
    for (int j = 0; j < ty; ++j) {
        runs.clear();
        const std::uint8_t* row = &occupied[static_cast<std::size_t>(j) * static_cast<std::size_t>(tx)];
        for (int i = 0; i < tx; ++i) {
            if (!row[i]) continue;
            const int first = i;
            while (i < tx && row[i]) ++i;
            runs.push_back({first, i});
        }
        if (runs == blockRuns) continue;
        closeBlock(j);
        blockRuns.swap(runs);
        blockFrom = j;
    }
    closeBlock(ty);
    return pixels;
}

}  // namespace arcomp
