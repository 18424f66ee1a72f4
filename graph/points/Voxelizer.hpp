#pragma once
// Polygon model -> voxel model. Every grid cell that a triangle touches
// (exact triangle/box overlap by separating axes) becomes a voxel whose
// colour is the mean of the colours of the triangles touching it.
//
//   std::vector<VoxelSource> parts = voxelSourcesOf(scene);   // meshes in world space
//   VoxelGrid grid = voxelize(parts, 200, [](float done) { ... });
//
// Why on the CPU and not the paper's OpenGL slab rendering: graph/ has no
// GL; the result must be the same on every machine (a GL rasterizer's
// coverage rules differ between drivers, and a thin triangle seen edge-on
// by a slab's camera leaves holes); and a CPU voxelizer is testable with
// plain unit tests. Baking is offline, so its speed matters little.
//
// Texture images are not sampled: a triangle's colour is its material's
// base colour times the mean of its vertex colours.

#include "graph/core/Geometry.hpp"
#include "graph/points/VoxelGrid.hpp"

#include <functional>
#include <span>
#include <vector>

namespace arcomp {

class Scene;

// One geometry placed in the world with one colour (alpha included).
struct VoxelSource {
    const Geometry* geometry = nullptr;
    glm::mat4 world{1.0f};
    glm::vec4 color{1.0f};
};

// Every mesh node of the scene with its world matrix and its material's
// base colour; call scene.update() first.
std::vector<VoxelSource> voxelSourcesOf(const Scene& scene);

// Called with the fraction of triangles done, about a hundred times.
using VoxelizeProgress = std::function<void(float)>;

// The grid is a cube around the sources' bounding box, its largest side
// divided into `resolution` cells. resolution must lie in [1, 4096].
VoxelGrid voxelize(std::span<const VoxelSource> sources, int resolution, const VoxelizeProgress& progress = {});

// True when the triangle (a, b, c) and the axis-aligned box (center,
// halfSize) share at least one point.
bool triangleOverlapsBox(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& center,
                         const glm::vec3& halfSize);

}  // namespace arcomp
