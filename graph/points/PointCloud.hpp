#pragma once
// Translucent points: flat arrays of positions and straight RGBA colours,
// all of one size (a voxel model's points are its cell centres, sized as
// one cell).
//
//   PointCloud cloud = pointCloudFromVoxels(readVoxelFile("tree.arvox"));

#include "graph/points/VoxelGrid.hpp"

#include <glm/glm.hpp>

#include <vector>

namespace arcomp {

struct PointCloud {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec4> colors;  // straight alpha, 0..1
    float pointSize = 1.0f;         // world-space diameter of a point's footprint

    std::size_t size() const { return positions.size(); }
};

inline PointCloud pointCloudFromVoxels(const VoxelGrid& grid) {
    PointCloud cloud;
    cloud.pointSize = grid.voxelSize;
    cloud.positions.reserve(grid.size());
    cloud.colors.reserve(grid.size());
    for (std::size_t i = 0; i < grid.size(); ++i) {
        cloud.positions.push_back(grid.center(i));
        cloud.colors.push_back(glm::vec4(grid.colors[i]) / 255.0f);
    }
    return cloud;
}

}  // namespace arcomp
