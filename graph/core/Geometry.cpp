#include "graph/core/Geometry.hpp"

#include <cmath>
#include <numbers>

namespace arcomp {

std::vector<glm::vec3> computeVertexNormals(const std::vector<glm::vec3>& positions,
                                            const std::vector<std::uint32_t>& indices) {
    std::vector<glm::vec3> normals(positions.size(), glm::vec3(0.0f));
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const std::uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
        // The cross product's length is twice the area: larger faces weigh more.
        const glm::vec3 n = glm::cross(positions[b] - positions[a], positions[c] - positions[a]);
        normals[a] += n;
        normals[b] += n;
        normals[c] += n;
    }
    for (glm::vec3& n : normals) {
        const float len = glm::length(n);
        n = len > 0.0f ? n / len : glm::vec3(0.0f, 0.0f, 1.0f);
    }
    return normals;
}

void Geometry::finalize() {
    if (normals.size() != positions.size()) normals = computeVertexNormals(positions, indices);
    box = boxAround(positions);
    bound = sphereAround(positions);
}

Geometry makeUvSphere(float radius, int slices, int stacks) {
    Geometry g;
    for (int j = 0; j <= stacks; ++j) {
        const float v = static_cast<float>(j) / static_cast<float>(stacks);
        const float phi = v * std::numbers::pi_v<float>;
        for (int i = 0; i <= slices; ++i) {
            const float u = static_cast<float>(i) / static_cast<float>(slices);
            const float theta = u * 2.0f * std::numbers::pi_v<float>;
            const glm::vec3 n{std::sin(phi) * std::cos(theta), std::cos(phi), std::sin(phi) * std::sin(theta)};
            g.positions.push_back(n * radius);
            g.normals.push_back(n);
            g.texcoords.push_back({u, v});
        }
    }
    const auto at = [slices](int i, int j) { return static_cast<std::uint32_t>(j * (slices + 1) + i); };
    for (int j = 0; j < stacks; ++j) {
        for (int i = 0; i < slices; ++i) {
            // Counter-clockwise seen from outside; the pole rows lose their
            // degenerate half.
            if (j != 0) g.indices.insert(g.indices.end(), {at(i, j), at(i + 1, j), at(i, j + 1)});
            if (j != stacks - 1) g.indices.insert(g.indices.end(), {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    }
    g.finalize();
    return g;
}

Geometry makeBox(const glm::vec3& size) {
    Geometry g;
    const glm::vec3 h = size * 0.5f;
    const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int axis = 0; axis < 3; ++axis) {
        for (float sign : {1.0f, -1.0f}) {
            const glm::vec3 n = axes[axis] * sign;
            const glm::vec3 u = axes[(axis + 1) % 3] * sign;
            const glm::vec3 v = axes[(axis + 2) % 3];
            const auto base = static_cast<std::uint32_t>(g.positions.size());
            for (int k = 0; k < 4; ++k) {
                const float su = (k == 1 || k == 2) ? 1.0f : -1.0f;
                const float sv = (k >= 2) ? 1.0f : -1.0f;
                g.positions.push_back(h * (n + u * su + v * sv));
                g.normals.push_back(n);
                g.texcoords.push_back({(su + 1) * 0.5f, (sv + 1) * 0.5f});
            }
            g.indices.insert(g.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        }
    }
    g.finalize();
    return g;
}

} // namespace arcomp
