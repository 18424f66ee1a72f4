#include "graph/silhouette/HoldoutMeshes.hpp"

namespace arcomp {

void HoldoutMeshes::add(Scene& scene, NodeId mesh, const SilhouetteMesh& silhouette, std::uint32_t material) {
    const std::uint32_t geometry = scene.addGeometry(silhouette.geometry());
    SilhouetteNode entry{{geometry, material}, silhouette.full, silhouette.regions, silhouette.ranges};
    if (mesh >= slot_.size()) slot_.resize(mesh + 1, kNone);
    if (slot_[mesh] != kNone) {
        entries_[slot_[mesh]] = std::move(entry);
        return;
    }
    slot_[mesh] = static_cast<std::uint32_t>(entries_.size());
    entries_.push_back(std::move(entry));
}

void HoldoutMeshes::addPosed(const Scene& scene, NodeId mesh, std::uint32_t material) {
    const MeshPart& cg = scene.meshPart(mesh);
    const auto indexCount = static_cast<std::uint32_t>(scene.geometry(cg.geometry).indices.size());
    SilhouetteNode entry{{cg.geometry, material, cg.skin}, {0, indexCount}, {}, {}};
    if (mesh >= slot_.size()) slot_.resize(mesh + 1, kNone);
    if (slot_[mesh] != kNone) {
        entries_[slot_[mesh]] = std::move(entry);
        return;
    }
    slot_[mesh] = static_cast<std::uint32_t>(entries_.size());
    entries_.push_back(std::move(entry));
}

std::optional<DrawItem> HoldoutMeshes::itemFor(const Scene& scene, const DrawItem& cg, const View& view) const {
    if (!has(cg.node)) return std::nullopt;
    const SilhouetteNode& s = entries_[slot_[cg.node]];
    const glm::vec3 localEye = glm::vec3(glm::inverse(scene.world(cg.node)) * glm::vec4(view.eye, 1.0f));
    const SilhouetteRange r = s.rangeFor(localEye);
    if (r.indexCount == 0) return std::nullopt;  // the renderer reads a count of 0 as "all lists"
    DrawItem item = cg;
    item.part = s.part;
    item.shading = Shading::Unlit;
    item.fade = 1.0f;
    item.firstIndex = r.firstIndex;
    item.indexCount = r.indexCount;
    item.model = nullptr;
    item.tint = glm::vec4(1.0f);
    return item;
}

std::size_t HoldoutMeshes::triangles() const {
    std::size_t n = 0;
    for (const SilhouetteNode& s : entries_)
        for (const SilhouetteRange& r : s.ranges) n += r.indexCount / 3;
    return n;
}

}  // namespace arcomp
