#include "graph/points/Voxelizer.hpp"

#include "graph/core/Scene.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace arcomp {

namespace {

// Separated when the triangle's projection onto `axis` misses the box's.
bool separatedOn(const glm::vec3& axis, const glm::vec3& v0, const glm::vec3& v1, const glm::vec3& v2,
                 const glm::vec3& h) {
    const float p0 = glm::dot(axis, v0), p1 = glm::dot(axis, v1), p2 = glm::dot(axis, v2);
    const float r = h.x * std::abs(axis.x) + h.y * std::abs(axis.y) + h.z * std::abs(axis.z);
    return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
}

struct Hit {
    std::uint64_t cell;
    glm::vec4 color;
};

}  // namespace

bool triangleOverlapsBox(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& center,
                         const glm::vec3& halfSize) {
    const glm::vec3 v0 = a - center, v1 = b - center, v2 = c - center;
    // The box's own axes: compare bounding intervals.
    for (int i = 0; i < 3; ++i) {
        if (std::min({v0[i], v1[i], v2[i]}) > halfSize[i] || std::max({v0[i], v1[i], v2[i]}) < -halfSize[i])
            return false;
    }
    // The triangle's plane.
    const glm::vec3 e0 = v1 - v0, e1 = v2 - v1, e2 = v0 - v2;
    const glm::vec3 n = glm::cross(e0, e1);
    const float r = halfSize.x * std::abs(n.x) + halfSize.y * std::abs(n.y) + halfSize.z * std::abs(n.z);
    if (std::abs(glm::dot(n, v0)) > r) return false;
    // Edge x box axis: the nine remaining candidate separating axes.
    const glm::vec3 edges[3] = {e0, e1, e2};
    const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const glm::vec3& e : edges)
        for (const glm::vec3& u : axes)
            if (separatedOn(glm::cross(u, e), v0, v1, v2, halfSize)) return false;
    return true;
}

std::vector<VoxelSource> voxelSourcesOf(const Scene& scene) {
    std::vector<VoxelSource> out;
    for (NodeId n = 0; n < scene.nodeCount(); ++n) {
        if (scene.kind(n) != NodeKind::Mesh) continue;
        const MeshPart& part = scene.meshPart(n);
        out.push_back({&scene.geometry(part.geometry), scene.world(n), scene.material(part.material).baseColor});
    }
    return out;
}

VoxelGrid voxelize(std::span<const VoxelSource> sources, int resolution, const VoxelizeProgress& progress) {
    if (resolution < 1 || resolution > 4096)
        throw std::invalid_argument("voxelize: resolution " + std::to_string(resolution) + " outside [1, 4096]");
    VoxelGrid grid;
    grid.resolution = resolution;
    Box box;
    std::size_t triangles = 0;
    for (const VoxelSource& s : sources) {
        for (const glm::vec3& p : s.geometry->positions) box.expand(glm::vec3(s.world * glm::vec4(p, 1.0f)));
        triangles += s.geometry->triangleCount();
    }
    if (box.empty()) return grid;
    const glm::vec3 size = box.size();
    const float extent = std::max({size.x, size.y, size.z, 1e-6f});
    // A hair of padding keeps faces lying on the box's maximum inside the grid.
    grid.voxelSize = extent * (1.0f + 1e-4f) / static_cast<float>(resolution);
    grid.origin = box.center() - glm::vec3(grid.voxelSize * static_cast<float>(resolution) * 0.5f);

    const auto n = static_cast<std::uint32_t>(resolution);
    const glm::vec3 half(grid.voxelSize * 0.5f);
    const float inv = 1.0f / grid.voxelSize;
    std::vector<Hit> hits;
    std::size_t done = 0, reportEvery = std::max<std::size_t>(1, triangles / 100);
    for (const VoxelSource& s : sources) {
        const Geometry& g = *s.geometry;
        for (std::size_t t = 0; t + 2 < g.indices.size(); t += 3, ++done) {
            if (progress && done % reportEvery == 0) progress(static_cast<float>(done) / static_cast<float>(triangles));
            const std::uint32_t ia = g.indices[t], ib = g.indices[t + 1], ic = g.indices[t + 2];
            if (std::max({ia, ib, ic}) >= g.positions.size()) continue;  // loaders check this; stay safe anyway
            const glm::vec3 a = glm::vec3(s.world * glm::vec4(g.positions[ia], 1.0f));
            const glm::vec3 b = glm::vec3(s.world * glm::vec4(g.positions[ib], 1.0f));
            const glm::vec3 c = glm::vec3(s.world * glm::vec4(g.positions[ic], 1.0f));
            glm::vec4 color = s.color;
            if (g.colors.size() == g.positions.size()) color *= (g.colors[ia] + g.colors[ib] + g.colors[ic]) / 3.0f;
            const glm::vec3 lo = (glm::min(glm::min(a, b), c) - grid.origin) * inv;
            const glm::vec3 hi = (glm::max(glm::max(a, b), c) - grid.origin) * inv;
            glm::uvec3 c0, c1;
            for (int i = 0; i < 3; ++i) {
                c0[i] = static_cast<std::uint32_t>(std::clamp(std::floor(lo[i]), 0.0f, float(n - 1)));
                c1[i] = static_cast<std::uint32_t>(std::clamp(std::floor(hi[i]), 0.0f, float(n - 1)));
            }
            for (std::uint32_t z = c0.z; z <= c1.z; ++z)
                for (std::uint32_t y = c0.y; y <= c1.y; ++y)
                    for (std::uint32_t x = c0.x; x <= c1.x; ++x) {
                        const glm::vec3 center = grid.origin + (glm::vec3(x, y, z) + 0.5f) * grid.voxelSize;
                        if (triangleOverlapsBox(a, b, c, center, half))
                            hits.push_back({x + std::uint64_t{n} * (y + std::uint64_t{n} * z), color});
                    }
        }
    }
    std::sort(hits.begin(), hits.end(), [](const Hit& l, const Hit& r) { return l.cell < r.cell; });
    for (std::size_t i = 0; i < hits.size();) {
        std::size_t j = i;
        glm::vec4 sum(0.0f);
        for (; j < hits.size() && hits[j].cell == hits[i].cell; ++j) sum += hits[j].color;
        const glm::vec4 mean = glm::clamp(sum / static_cast<float>(j - i), 0.0f, 1.0f);
        const std::uint64_t cell = hits[i].cell, nn = n;
        grid.cells.emplace_back(cell % nn, (cell / nn) % nn, cell / (nn * nn));
        grid.colors.emplace_back(glm::round(mean * 255.0f));
        i = j;
    }
    if (progress) progress(1.0f);
    return grid;
}

}  // namespace arcomp
