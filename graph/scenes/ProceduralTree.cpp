#include "graph/scenes/ProceduralTree.hpp"

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <random>

namespace arcomp {

namespace {

void addCylinder(Geometry& g, glm::vec3 a, glm::vec3 b, float ra, float rb, int segments) {
    const glm::vec3 axis = glm::normalize(b - a);
    const glm::vec3 side =
        glm::normalize(glm::cross(axis, std::abs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0)));
    const glm::vec3 other = glm::cross(axis, side);
    const auto base = static_cast<std::uint32_t>(g.positions.size());
    for (int i = 0; i < segments; ++i) {
        const float t = glm::two_pi<float>() * static_cast<float>(i) / static_cast<float>(segments);
        const glm::vec3 d = side * std::cos(t) + other * std::sin(t);
        g.positions.push_back(a + d * ra);
        g.positions.push_back(b + d * rb);
    }
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(segments); ++i) {
        const std::uint32_t j = (i + 1) % static_cast<std::uint32_t>(segments);
        g.indices.insert(g.indices.end(), {base + 2 * i, base + 2 * j, base + 2 * i + 1, base + 2 * i + 1, base + 2 * j,
                                           base + 2 * j + 1});
    }
}

void addLeaf(Geometry& g, glm::vec3 center, glm::vec3 u, glm::vec3 v) {
    const auto base = static_cast<std::uint32_t>(g.positions.size());
    g.positions.insert(g.positions.end(),
                       {center - u - v * 0.3f, center + u * 0.2f - v, center + u, center - u * 0.2f + v});
    g.indices.insert(g.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

void grow(ProceduralTree& t, std::mt19937& rng, glm::vec3 from, glm::vec3 dir, float length, float radius, int depth) {
    const glm::vec3 to = from + dir * length;
    addCylinder(t.wood, from, to, radius, radius * 0.7f, 8);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    if (depth == 0) {
        // A leaf cluster: flat leaves scattered in a ball around the tip.
        for (int i = 0; i < 7; ++i) {
            glm::vec3 offset(u(rng), u(rng), u(rng));
            if (glm::length(offset) > 1.0f) offset = glm::normalize(offset);
            const glm::vec3 a = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(0.01f));
            const glm::vec3 b = glm::normalize(
                glm::cross(a, glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(0.02f, 0, 0))));
            addLeaf(t.leaves, to + offset * 0.16f, a * 0.037f, b * 0.021f);
        }
        return;
    }
    const int children = depth >= 3 ? 3 : 4;
    for (int c = 0; c < children; ++c) {
        const float turn =
            glm::two_pi<float>() * (static_cast<float>(c) + 0.3f * u(rng)) / static_cast<float>(children);
        const glm::vec3 side =
            glm::normalize(glm::cross(dir, std::abs(dir.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0)));
        const glm::vec3 other = glm::cross(dir, side);
        const glm::vec3 spread = side * std::cos(turn) + other * std::sin(turn);
        const glm::vec3 next = glm::normalize(dir * 0.75f + spread * 0.65f + glm::vec3(0, 0.2f, 0));
        grow(t, rng, to, next, length * (0.68f + 0.08f * u(rng)), radius * 0.62f, depth - 1);
    }
}

}  // namespace

std::vector<VoxelSource> ProceduralTree::voxelSources() const {
    return {{&wood, glm::mat4(1.0f), woodColor}, {&leaves, glm::mat4(1.0f), leafColor}};
}

ProceduralTree growTree(std::uint32_t seed) {
    ProceduralTree t;
    std::mt19937 rng(seed);
    grow(t, rng, {0, 0, 0}, {0, 1, 0}, 0.9f, 0.045f, 4);
    t.wood.finalize();
    t.leaves.finalize();
    return t;
}

}  // namespace arcomp
