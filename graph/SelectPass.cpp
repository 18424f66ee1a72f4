#include "graph/SelectPass.hpp"

#include "graph/Frustum.hpp"

namespace arcomp {

namespace {

struct SelectPass {
    const Scene& scene;
    const View& view;
    const SelectSettings& settings;
    DrawList& out;
    Frustum frustum;
    std::span<const NodeId> order;
    std::span<const std::uint32_t> end;

    // Visits the subtree at `pos`. Once a node lies wholly inside the
    // frustum, nothing below it is tested again.
    void visit(std::uint32_t pos, bool inside) {
        const NodeId node = order[pos];
        ++out.nodesVisited;
        const Sphere& bound = scene.worldBound(node);
        if (!inside) {
            const Containment c = frustum.classify(bound);
            if (c == Containment::Outside) {
                ++out.nodesCulled;
                return;
            }
            inside = c == Containment::Inside;
        }
        switch (scene.kind(node)) {
        case NodeKind::Mesh:
            out.items.push_back({node, scene.meshPart(node), glm::length(bound.center - view.eye),
                                 view.projectedArea(bound), 0, settings.shading});
            break;
        case NodeKind::SilhouetteRegion:
            if (settings.silhouettes && scene.payload(node) < settings.silhouettes->nodes.size()) {
                const SilhouetteNode& s = settings.silhouettes->nodes[scene.payload(node)];
                const glm::vec3 localEye = glm::vec3(glm::inverse(scene.world(node)) * glm::vec4(view.eye, 1.0f));
                const SilhouetteRange r = s.rangeFor(localEye);
                out.items.push_back({node, s.part, glm::length(bound.center - view.eye), view.projectedArea(bound), 0,
                                     settings.shading, r.firstIndex, r.indexCount});
            }
            break;
        default:
            break;
        }
        for (std::uint32_t child = pos + 1; child < end[pos]; child = end[child]) visit(child, inside);
    }
};

} // namespace

void select(const Scene& scene, const View& view, const SelectSettings& settings, DrawList& out) {
    out.clear();
    if (scene.order().empty()) return;
    SelectPass pass{scene, view, settings, out, Frustum::fromViewProjection(view.viewProjection()),
                    scene.order(), scene.subtreeEnd()};
    pass.visit(0, false);
}

} // namespace arcomp
