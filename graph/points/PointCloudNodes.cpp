#include "graph/points/PointCloudNodes.hpp"

#include <stdexcept>

namespace arcomp {

NodeId PointCloudNodes::add(Scene& scene, NodeId parent, LdiSet set, std::string name) {
    Sphere bound = sphereAround(set.cloud.positions);
    if (!bound.empty()) bound.radius += set.cloud.pointSize;  // the footprints reach past the centres
    const auto index = static_cast<std::uint32_t>(sets_.size());
    sets_.push_back(std::make_unique<LdiSet>(std::move(set)));
    const NodeId node = scene.addNode(parent, NodeKind::PointCloud, index, std::move(name));
    scene.setLocalBound(node, bound);
    return node;
}

const LdiSet& PointCloudNodes::at(const Scene& scene, NodeId node) const {
    if (node >= scene.nodeCount() || scene.kind(node) != NodeKind::PointCloud || scene.payload(node) >= sets_.size())
        throw std::out_of_range("node " + std::to_string(node) + " is not a point cloud of this table");
    return *sets_[scene.payload(node)];
}

}  // namespace arcomp
