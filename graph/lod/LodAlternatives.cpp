#include "graph/lod/LodAlternatives.hpp"

#include <algorithm>

namespace arcomp {

LodAlternatives::LodAlternatives(const Scene& scene) : group_(scene.nodeCount(), kNone) {
    groupStart_.push_back(0);
    for (NodeId n = 0; n < scene.nodeCount(); ++n) {
        if (scene.kind(n) != NodeKind::Lod) continue;
        const std::vector<NodeId> children = scene.children(n);
        if (children.size() < 2) continue;
        const bool meshesOnly = std::all_of(children.begin(), children.end(), [&](NodeId c) {
            return scene.kind(c) == NodeKind::Mesh && scene.children(c).empty();
        });
        if (!meshesOnly) continue;
        const auto g = static_cast<std::uint32_t>(groupStart_.size() - 1);
        for (NodeId c : children) {
            group_[c] = g;
            levels_.push_back(c);
        }
        groupStart_.push_back(static_cast<std::uint32_t>(levels_.size()));
    }
}

std::uint8_t LodAlternatives::levelCount(NodeId mesh) const {
    if (mesh >= group_.size() || group_[mesh] == kNone) return 1;
    const std::uint32_t g = group_[mesh];
    return static_cast<std::uint8_t>(groupStart_[g + 1] - groupStart_[g]);
}

NodeId LodAlternatives::levelNode(NodeId mesh, std::uint8_t level) const {
    if (mesh >= group_.size() || group_[mesh] == kNone) return mesh;
    const std::uint32_t g = group_[mesh];
    const std::uint32_t count = groupStart_[g + 1] - groupStart_[g];
    return levels_[groupStart_[g] + std::min<std::uint32_t>(level, count - 1)];
}

}  // namespace arcomp
