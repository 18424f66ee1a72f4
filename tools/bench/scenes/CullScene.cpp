#include "tools/bench/scenes/CullScene.hpp"

#include <algorithm>
#include <cmath>

namespace arcomp {

namespace {

// Leaf groups are 4x4 blocks of grid cells; above them a quadtree splits the
// rectangle of blocks [bx0, bx1) x [bz0, bz1) until one block remains.
struct QuadtreeBuilder {
    CullScene& scene;
    std::uint32_t side;
    std::uint32_t objects;

    void fill(std::uint32_t group, std::uint32_t bx0, std::uint32_t bx1, std::uint32_t bz0, std::uint32_t bz1) {
        if (bx1 - bx0 == 1 && bz1 - bz0 == 1) {
            for (std::uint32_t row = bz0 * 4; row < std::min(bz0 * 4 + 4, side); ++row)
                for (std::uint32_t col = bx0 * 4; col < std::min(bx0 * 4 + 4, side); ++col) {
                    const std::uint32_t k = row * side + col;
                    if (k < objects) scene.groups[group].objects.push_back(k);
                }
            return;
        }
        const std::uint32_t xm = bx1 - bx0 > 1 ? (bx0 + bx1) / 2 : bx1;
        const std::uint32_t zm = bz1 - bz0 > 1 ? (bz0 + bz1) / 2 : bz1;
        const std::uint32_t xs[3] = {bx0, xm, bx1}, zs[3] = {bz0, zm, bz1};
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) {
                if (xs[i] == xs[i + 1] || zs[j] == zs[j + 1]) continue;
                // Skip quadrants past the last filled row: they hold nothing.
                if (zs[j] * 4 * side >= objects) continue;
                const auto child = static_cast<std::uint32_t>(scene.groups.size());
                scene.groups.emplace_back();
                scene.groups[group].groups.push_back(child);
                fill(child, xs[i], xs[i + 1], zs[j], zs[j + 1]);
            }
    }
};

}  // namespace

CullScene makeCullScene(std::uint32_t objects, CullLayout layout) {
    CullScene s;
    const auto side = static_cast<std::uint32_t>(std::ceil(std::sqrt(static_cast<double>(objects))));
    s.halfSide = static_cast<float>(side) * kCullSpacing * 0.5f;
    const float offset = (static_cast<float>(side) - 1.0f) * 0.5f;
    for (std::uint32_t k = 0; k < objects; ++k) {
        const float col = static_cast<float>(k % side), row = static_cast<float>(k / side);
        s.positions.push_back({(col - offset) * kCullSpacing, 0.0f, (row - offset) * kCullSpacing});
    }
    s.groups.emplace_back();
    if (layout == CullLayout::Flat || objects == 0) {
        for (std::uint32_t k = 0; k < objects; ++k) s.groups[0].objects.push_back(k);
    } else {
        const std::uint32_t blocks = (side + 3) / 4;
        QuadtreeBuilder{s, side, objects}.fill(0, 0, blocks, 0, blocks);
    }
    return s;
}

CullCamera cullCamera(const CullScene& s, int frame, int frames) {
    const float t = frames > 1 ? static_cast<float>(frame) / static_cast<float>(frames - 1) : 0.0f;
    const float r = s.halfSide;
    const glm::vec3 eye{-r + 2.0f * r * t, 10.0f, -0.5f * r + r * t};
    return {eye, eye + glm::vec3(35.36f, -10.0f, 35.36f)};
}

}  // namespace arcomp
