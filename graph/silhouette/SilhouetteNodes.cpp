#include "graph/silhouette/SilhouetteNodes.hpp"

namespace arcomp {

SilhouetteRange SilhouetteNode::rangeFor(const glm::vec3& localEye) const {
    for (std::size_t i = 0; i < regions.size(); ++i)
        if (regions[i].contains(localEye)) return ranges[i];
    return full;
}

NodeId addSilhouetteNode(Scene& scene, NodeId parent, SilhouetteNodes& table, const SilhouetteMesh& mesh,
                         std::uint32_t material, std::string name) {
    Geometry g = mesh.geometry();
    const Sphere bound = g.bound;
    const std::uint32_t geometry = scene.addGeometry(std::move(g));
    table.nodes.push_back({{geometry, material}, mesh.full, mesh.regions, mesh.ranges});
    const NodeId node = scene.addNode(parent, NodeKind::SilhouetteRegion,
                                      static_cast<std::uint32_t>(table.nodes.size() - 1), std::move(name));
    scene.setLocalBound(node, bound);
    return node;
}

}  // namespace arcomp
