#include "graph/lod/LodLevels.hpp"
#include "graph/core/Check.hpp"

#include <meshoptimizer.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace arcomp {

namespace {

// Keeps only the vertices `indices` use, in first-use order, with all their
// attributes.
Geometry compacted(const Geometry& g, const std::vector<std::uint32_t>& indices) {
    std::vector<std::uint32_t> remap(g.positions.size(), ~0u);
    Geometry out;
    for (std::uint32_t i : indices) {
        if (remap[i] == ~0u) {
            remap[i] = static_cast<std::uint32_t>(out.positions.size());
            out.positions.push_back(g.positions[i]);
            if (!g.normals.empty()) out.normals.push_back(g.normals[i]);
            if (!g.texcoords.empty()) out.texcoords.push_back(g.texcoords[i]);
            if (!g.texcoords1.empty()) out.texcoords1.push_back(g.texcoords1[i]);
            if (!g.tangents.empty()) out.tangents.push_back(g.tangents[i]);
            if (!g.colors.empty()) out.colors.push_back(g.colors[i]);
            if (!g.joints.empty()) out.joints.push_back(g.joints[i]);
            if (!g.weights.empty()) out.weights.push_back(g.weights[i]);
        }
        out.indices.push_back(remap[i]);
    }
    // A kept vertex keeps its tangent: the full mesh's surface frame, close
    // enough on the coarser surface that a level is drawn at a distance.
    out.tangentsGenerated = g.tangentsGenerated;
    out.finalize();
    return out;
}

}  // namespace

std::vector<LodLevel> simplifyLevels(const Geometry& g, std::span<const float> ratios) {
    const std::size_t triangles = g.triangleCount();
    const float* positions = &g.positions.data()->x;
    const std::size_t vertexCount = g.positions.size();
    std::vector<std::uint32_t> shadow(g.indices.size());
    meshopt_generateShadowIndexBuffer(shadow.data(), g.indices.data(), g.indices.size(), positions, vertexCount,
                                      sizeof(glm::vec3), sizeof(glm::vec3));
    const float scale = meshopt_simplifyScale(positions, vertexCount, sizeof(glm::vec3));

    std::vector<LodLevel> levels;
    for (float ratio : ratios) {
        if (!(ratio > 0.0f && ratio <= 1.0f)) throw std::invalid_argument("LOD ratio must be in (0, 1]");
        if (ratio == 1.0f || triangles == 0) {
            levels.push_back({g, ratio, 0.0f});
            continue;
        }
        const std::size_t targetTriangles =
            std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(triangles * ratio)));
        std::vector<std::uint32_t> out(g.indices.size());
        float relativeError = 0.0f;
        // Target error 1 (the whole extent): the triangle count decides.
        std::size_t count = meshopt_simplify(out.data(), shadow.data(), shadow.size(), positions, vertexCount,
                                             sizeof(glm::vec3), targetTriangles * 3, 1.0f, 0, &relativeError);
        if (count > targetTriangles * 3 * 11 / 10) {
            count = meshopt_simplifySloppy(out.data(), shadow.data(), shadow.size(), positions, vertexCount,
                                           sizeof(glm::vec3), targetTriangles * 3, 1.0f, &relativeError);
        }
        out.resize(count);
        levels.push_back({compacted(g, out), ratio, relativeError * scale});
    }
    return levels;
}

NodeId addGeneratedLod(Scene& scene, LodTable& lods, NodeId parent, MeshPart part, std::span<const float> ratios,
                       const LodNode& settings) {
    return addLodLevels(scene, lods, parent, part, simplifyLevels(scene.geometry(part.geometry), ratios), settings);
}

NodeId addLodLevels(Scene& scene, LodTable& lods, NodeId parent, MeshPart part, std::vector<LodLevel> levels,
                    const LodNode& settings) {
    ARCOMP_CHECK(settings.levelCount == levels.size(), "one level per threshold band");
    const Geometry& source = scene.geometry(part.geometry);
    LodNode node = settings;
    node.center = source.bound.center;
    node.meanRadius = meanRadius(source.positions, source.bound.center);
    const NodeId lod = scene.addNode(parent, NodeKind::Lod, lods.add(node));
    for (LodLevel& level : levels) {
        const std::uint32_t g = level.ratio == 1.0f ? part.geometry : scene.addGeometry(std::move(level.geometry));
        // Every level keeps the part's skin: compacted() carried the joints
        // and weights of the vertices it kept.
        scene.addMesh(lod, {g, part.material, part.skin});
    }
    return lod;
}

}  // namespace arcomp
