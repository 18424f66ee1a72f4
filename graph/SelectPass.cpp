#include "graph/SelectPass.hpp"

#include "graph/Frustum.hpp"
#include "graph/Lod.hpp"

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
    float pixelScale;
    glm::vec3 gaze;

    // Visits the subtree at `pos`. Once a node lies wholly inside the
    // frustum, nothing below it is tested again. `level` and `fade` come from
    // the nearest LOD node above.
    void visit(std::uint32_t pos, bool inside, std::uint8_t level, float fade) {
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
                                 view.projectedArea(bound), level, settings.shading, fade});
            break;
        case NodeKind::Lod:
            visitLod(pos, node, bound, inside, fade);
            return;  // its children are levels: only the chosen ones are visited
        case NodeKind::SilhouetteRegion:
            if (settings.silhouettes && scene.payload(node) < settings.silhouettes->nodes.size()) {
                const SilhouetteNode& s = settings.silhouettes->nodes[scene.payload(node)];
                const glm::vec3 localEye = glm::vec3(glm::inverse(scene.world(node)) * glm::vec4(view.eye, 1.0f));
                const SilhouetteRange r = s.rangeFor(localEye);
                out.items.push_back({node, s.part, glm::length(bound.center - view.eye), view.projectedArea(bound), level,
                                     settings.shading, fade, r.firstIndex, r.indexCount});
            }
            break;
        default:
            break;
        }
        for (std::uint32_t child = pos + 1; child < end[pos]; child = end[child]) visit(child, inside, level, fade);
    }

    void visitLod(std::uint32_t pos, NodeId node, const Sphere& bound, bool inside, float fade) {
        if (settings.lod == nullptr) {
            visitLevel(pos, 0, inside, fade);
            return;
        }
        LodTable& lods = *settings.lod;
        const std::uint32_t i = scene.payload(node);
        const LodNode& n = lods.node(i);
        LodInputs in;
        in.distance = glm::length(bound.center - view.eye);
        if (n.policy == LodPolicy::ScreenSize || n.policy == LodPolicy::ScreenSizeTimesAcuity)
            in.pixels = in.distance > bound.radius ? 2.0f * bound.radius / in.distance * pixelScale
                                                   : static_cast<float>(view.viewport.y);
        if (n.policy == LodPolicy::GazeAcuity || n.policy == LodPolicy::ScreenSizeTimesAcuity)
            in.acuity = lods.acuity(i, scene.world(node), view.eye, gaze, settings.timeSeconds);
        const LodChoice c = lods.choose(i, in, settings.timeSeconds);
        visitLevel(pos, c.level, inside, fade * c.fade);
        if (c.fadingLevel != kNoLevel) visitLevel(pos, c.fadingLevel, inside, fade * (1.0f - c.fade));
    }

    // Visits the LOD node's child number `level`, or its last child when it
    // has fewer.
    void visitLevel(std::uint32_t lodPos, std::uint8_t level, bool inside, float fade) {
        std::uint32_t child = lodPos + 1;
        if (child >= end[lodPos]) return;
        std::uint8_t shown = 0;
        while (shown < level && end[child] < end[lodPos]) {
            child = end[child];
            ++shown;
        }
        visit(child, inside, shown, fade);
    }
};

} // namespace

void select(const Scene& scene, const View& view, const SelectSettings& settings, DrawList& out) {
    out.clear();
    if (scene.order().empty()) return;
    const glm::vec3 gaze = glm::length(settings.gaze) > 0.0f ? glm::normalize(settings.gaze) : view.forward;
    SelectPass pass{scene,          view,           settings,          out, Frustum::fromViewProjection(view.viewProjection()),
                    scene.order(), scene.subtreeEnd(), view.pixelScale(), gaze};
    pass.visit(0, false, 0, 1.0f);
}

} // namespace arcomp
