#include "graph/points/Voxelizer.hpp"

#include <gtest/gtest.h>

#include <set>

using namespace arcomp;

TEST(Voxelizer, triangleBoxOverlapUsesEverySeparatingAxis) {
    const glm::vec3 c(0.0f), h(0.5f);
    EXPECT_TRUE(triangleOverlapsBox({-2, 0, 0}, {2, 0, 0}, {0, 2, 0}, c, h)) << "cuts through the box";
    EXPECT_TRUE(triangleOverlapsBox({-0.1f, -0.1f, 0}, {0.1f, -0.1f, 0}, {0, 0.1f, 0}, c, h)) << "wholly inside";
    EXPECT_FALSE(triangleOverlapsBox({2, 0, 0}, {3, 0, 0}, {2, 1, 0}, c, h)) << "box axis separates";
    EXPECT_FALSE(triangleOverlapsBox({-2, -2, 0.7f}, {2, -2, 0.7f}, {0, 2, 0.7f}, c, h)) << "plane separates";
    // Bounding boxes overlap and the plane cuts the box, yet an edge x axis
    // cross product separates: a slanted triangle passing beside an edge.
    EXPECT_FALSE(triangleOverlapsBox({-0.8f, -0.2f, 0.0f}, {-0.8f, -0.8f, -0.8f}, {-0.1f, -0.6f, -1.4f}, c, h));
    EXPECT_TRUE(triangleOverlapsBox({0.5f, 0.5f, 0.5f}, {3, 0.5f, 0.5f}, {0.5f, 3, 0.5f}, c, h)) << "touching a corner";
}

TEST(Voxelizer, boxSurfaceFillsTheOuterShellOfTheGrid) {
    Geometry box = makeBox(glm::vec3(1.0f));
    box.finalize();
    const std::vector<VoxelSource> sources = {{&box, glm::mat4(1.0f), {0.2f, 0.4f, 0.6f, 0.5f}}};
    int reports = 0;
    const VoxelGrid grid = voxelize(sources, 10, [&](float) { ++reports; });
    EXPECT_EQ(grid.size(), static_cast<std::size_t>(10 * 10 * 10 - 8 * 8 * 8));
    EXPECT_GT(reports, 0);
    EXPECT_NEAR(grid.voxelSize, 0.1f, 1e-4f);
    std::set<std::uint64_t> cells;
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const glm::u16vec3 c = grid.cells[i];
        const bool onShell = c.x == 0 || c.y == 0 || c.z == 0 || c.x == 9 || c.y == 9 || c.z == 9;
        EXPECT_TRUE(onShell);
        EXPECT_EQ(grid.colors[i], glm::u8vec4(51, 102, 153, 128));
        EXPECT_TRUE(i == 0 || grid.linearIndex(i - 1) < grid.linearIndex(i)) << "sorted, no repeats";
    }
}

TEST(Voxelizer, worldMatrixPlacesTheGrid) {
    Geometry box = makeBox(glm::vec3(1.0f));
    box.finalize();
    glm::mat4 world(1.0f);
    world[3] = glm::vec4(5, 0, 0, 1);
    const std::vector<VoxelSource> sources = {{&box, world, glm::vec4(1.0f)}};
    const VoxelGrid grid = voxelize(sources, 4);
    EXPECT_NEAR(grid.origin.x, 4.5f, 1e-3f);
    EXPECT_THROW(voxelize(sources, 0), std::invalid_argument);
}
