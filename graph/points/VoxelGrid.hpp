#pragma once
// A sparse voxel model: the occupied cells of an N x N x N grid, each with a
// straight (not premultiplied) RGBA8 colour. Cells are kept sorted by their
// linear index x + N*(y + N*z), so that two grids compare cell by cell and a
// file written from one reads back identical.
//
//   VoxelGrid g = voxelize(parts, 200);
//   glm::vec3 p = g.center(0);   // world position of the first voxel

#include <glm/glm.hpp>
#include <glm/gtc/type_precision.hpp>

#include <cstdint>
#include <vector>

namespace arcomp {

struct VoxelGrid {
    int resolution = 0;      // N: the grid has N^3 cells
    glm::vec3 origin{0.0f};  // world position of the grid's minimum corner
    float voxelSize = 1.0f;  // edge length of one cell in world units
    std::vector<glm::u16vec3> cells;
    std::vector<glm::u8vec4> colors;

    std::size_t size() const { return cells.size(); }
    glm::vec3 center(std::size_t i) const { return origin + (glm::vec3(cells[i]) + 0.5f) * voxelSize; }
    std::uint64_t linearIndex(std::size_t i) const {
        const auto n = static_cast<std::uint64_t>(resolution);
        return cells[i].x + n * (cells[i].y + n * cells[i].z);
    }
};

}  // namespace arcomp
