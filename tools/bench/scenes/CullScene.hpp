#pragma once
// The scene of `arcomp-bench cull`, described once so that arcomp and
// OpenSceneGraph build the very same one (issue 3): N objects on a square
// grid in the XZ plane, spacing 4, each a transform over an LOD node with
// three unit spheres (about 2000, 500 and 50 triangles), switched at 50 and
// 200 units from the eye; flat under the root or in a quadtree of groups
// with 16 objects per leaf group; a camera sweeping diagonally across.
//
//   CullScene s = makeCullScene(100000, CullLayout::Tree);
//   for (int f = 0; f < frames; ++f) CullCamera c = cullCamera(s, f, frames);

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace arcomp {

enum class CullLayout { Flat, Tree };

struct CullGroup {
    std::vector<std::uint32_t> groups;   // child groups, indices into CullScene::groups
    std::vector<std::uint32_t> objects;  // objects directly under this group
};

struct CullScene {
    std::vector<glm::vec3> positions;  // object k's grid position
    std::vector<CullGroup> groups;     // groups[0] is the root
    float halfSide = 0.0f;             // R: half the grid's side in world units
};

inline constexpr float kCullSpacing = 4.0f;
inline constexpr float kCullRanges[2] = {50.0f, 200.0f};
// Sphere tessellations (slices, stacks): 2000, 504 and 48 triangles. Slices
// divisible by 4 and even stacks make the bound exactly the unit sphere.
inline constexpr int kCullSphereSlices[3] = {40, 28, 8};
inline constexpr int kCullSphereStacks[3] = {26, 10, 4};

CullScene makeCullScene(std::uint32_t objects, CullLayout layout);

struct CullCamera {
    glm::vec3 eye;
    glm::vec3 target;
};
// Frame f of `frames`: eye = (-R + 2R·t, 10, -0.5R + R·t), t = f / (frames - 1),
// looking at eye + (35.36, -10, 35.36).
CullCamera cullCamera(const CullScene& s, int frame, int frames);
inline constexpr float kCullFovyDegrees = 60.0f;
inline constexpr int kCullWidth = 1920, kCullHeight = 1080;
inline constexpr float kCullNear = 0.1f, kCullFar = 10000.0f;

// What one frame's select gave: visible objects and how many at each level.
struct CullFrameCounts {
    std::uint32_t visible = 0;
    std::uint32_t levels[3] = {0, 0, 0};
    bool operator==(const CullFrameCounts&) const = default;
};

struct CullRun {
    std::vector<double> msPerFrame;       // measured frames only
    std::vector<CullFrameCounts> counts;  // per measured frame
};

}  // namespace arcomp
