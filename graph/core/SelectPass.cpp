#include "graph/core/SelectPass.hpp"
#include "graph/core/Check.hpp"

#include "graph/core/Frustum.hpp"
#include "graph/grouping/GroupingNodes.hpp"
#include "graph/lod/Lod.hpp"

namespace arcomp {

namespace {

struct SelectPass {
    World& world;
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
            if (world.holdouts.has(node))
                out.holdouts.push_back({static_cast<std::uint32_t>(out.items.size()), glm::dot(bound.center - view.eye, view.forward)});
            out.items.push_back({node, scene.meshPart(node), glm::length(bound.center - view.eye),
                                 view.projectedArea(bound), level, settings.shading, fade});
            break;
        case NodeKind::PointCloud:
            out.pointClouds.push_back({node, glm::length(bound.center - view.eye)});
            break;
        case NodeKind::Lod:
            visitLod(pos, node, bound, inside, fade);
            return;  // its children are levels: only the chosen ones are visited
        case NodeKind::Grouping:
            if (settings.grouping) {
                visitGrouping(pos, node, inside, level, fade);
                return;  // its children are reached through the grouping tree
            }
            break;
        case NodeKind::SilhouetteRegion:
            {
                ARCOMP_CHECK(scene.payload(node) < world.silhouettes.nodes.size(), "a silhouette node has its entry in world.silhouettes");
                const SilhouetteNode& s = world.silhouettes.nodes[scene.payload(node)];
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
        if (!settings.lod) {
            visitLevel(pos, 0, inside, fade);
            return;
        }
        LodTable& lods = world.lods;
        const std::uint32_t i = scene.payload(node);
        ARCOMP_CHECK(i < lods.size(), "an LOD node has its entry in world.lods");
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

    // The paper's NodeChoice over the grouping tree (DESIGN.md §2): a group
    // in view whose Ω at its eye distance is below Ωt is drawn as its proxy;
    // otherwise its two children are tried; an object is visited as a
    // subtree, so its own LOD node picks its level.
    void visitGrouping(std::uint32_t pos, NodeId node, bool inside, std::uint8_t level, float fade) {
        ARCOMP_CHECK(scene.payload(node) < world.grouping.nodes.size(), "a grouping node has its entry in world.grouping");
        GroupingNode& g = world.grouping.nodes[scene.payload(node)];
        const GroupingTree& tree = g.tree;
        if (tree.objectCount() != g.objects.size()) return;  // not built: draws nothing rather than guess
        refreshObjectPositions(pos, g);
        if (g.proxyModel.size() < tree.nodeCount()) g.proxyModel.resize(tree.nodeCount());
        const GroupingParams& params = tree.params();
        auto& stack = g.pending;
        stack.clear();
        for (std::uint32_t r : tree.roots()) stack.push_back({r, inside});
        while (!stack.empty()) {
            auto [t, in] = stack.back();
            stack.pop_back();
            if (tree.isLeaf(t)) {
                visit(g.objectPosition[t], in, level, fade);
                continue;
            }
            ++out.nodesVisited;
            const Box& box = tree.item(t).box;
            const Sphere& s = tree.bound(t);
            if (!in) {
                const Containment c = frustum.classify(s);
                if (c == Containment::Outside) {
                    ++out.nodesCulled;
                    continue;
                }
                in = c == Containment::Inside;
            }
            const float leye = glm::length(s.center - view.eye);
            if (omegaAt(tree.mergeOmega0(t), leye, params) >= g.omegaT) {
                stack.push_back({tree.right(t), in});
                stack.push_back({tree.left(t), in});
                continue;
            }
            DrawItem item{node, g.boxPart, leye, view.projectedArea(s), level, settings.shading, fade};
            if (g.proxy == GroupingProxy::Impostor && g.impostorFits(t)) {
                item.part = {g.quadGeometry, g.impostorMaterial[t]};
                g.proxyModel[t] = billboardModel(s, view.eye);
            } else {
                g.proxyModel[t] = boxProxyModel(box);
                item.tint = glm::vec4(tree.item(t).color, g.proxyAlpha);
            }
            item.model = &g.proxyModel[t];
            out.items.push_back(item);
        }
    }

    // Object i is the grouping node's i-th child; its position moves when
    // the scene's structure changes.
    void refreshObjectPositions(std::uint32_t pos, GroupingNode& g) {
        bool valid = g.objectPosition.size() == g.objects.size();
        for (std::size_t i = 0; valid && i < g.objects.size(); i += std::max<std::size_t>(1, g.objects.size() / 8))
            valid = g.objectPosition[i] < order.size() && order[g.objectPosition[i]] == g.objects[i];
        if (valid) return;
        g.objectPosition.clear();
        for (std::uint32_t child = pos + 1; child < end[pos]; child = end[child]) g.objectPosition.push_back(child);
        for (std::size_t i = 0; i < g.objects.size(); ++i)
            ARCOMP_CHECK(i < g.objectPosition.size() && order[g.objectPosition[i]] == g.objects[i], "a grouping node's children do not change after buildGrouping");
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

void select(World& world, const View& view, const SelectSettings& settings, DrawList& out) {
    const Scene& scene = world.scene;
    out.clear();
    if (scene.order().empty()) return;
    const glm::vec3 gaze = glm::length(settings.gaze) > 0.0f ? glm::normalize(settings.gaze) : view.forward;
    SelectPass pass{world,         scene,         view, settings, out, Frustum::fromViewProjection(view.viewProjection()),
                    scene.order(), scene.subtreeEnd(), view.pixelScale(), gaze};
    pass.visit(0, false, 0, 1.0f);
}

} // namespace arcomp
