#include "graph/silhouette/FlatMesh.hpp"

#include <meshoptimizer.h>

namespace arcomp {

FlatMesh flattenModel(const ParsedModel& model) {
    FlatMesh out;
    std::vector<glm::mat4> world(model.nodes.size(), glm::mat4(1.0f));
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        const ModelNode& node = model.nodes[n];
        // Parents come first, so the parent's world matrix is ready.
        world[n] = node.parent >= 0 && static_cast<std::size_t>(node.parent) < n
                       ? world[static_cast<std::size_t>(node.parent)] * node.local
                       : node.local;
        for (const MeshPart& part : node.parts) {
            if (part.geometry >= model.geometries.size()) continue;
            const Geometry& g = model.geometries[part.geometry];
            const auto base = static_cast<std::uint32_t>(out.positions.size());
            for (const glm::vec3& p : g.positions) out.positions.push_back(glm::vec3(world[n] * glm::vec4(p, 1.0f)));
            for (std::uint32_t i : g.indices) out.indices.push_back(base + i);
        }
    }
    return out;
}

std::vector<std::uint32_t> simplifyToTriangles(std::span<const glm::vec3> positions,
                                               std::span<const std::uint32_t> indices, std::size_t triangles) {
    std::vector<std::uint32_t> out(indices.size());
    if (indices.empty()) return out;
    out.resize(meshopt_simplify(out.data(), indices.data(), indices.size(), &positions[0].x, positions.size(),
                                sizeof(glm::vec3), triangles * 3, 1.0f, 0, nullptr));
    return out;
}

}  // namespace arcomp
