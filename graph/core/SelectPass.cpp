#include "graph/core/SelectPass.hpp"
#include "graph/core/Check.hpp"

#include "graph/core/DiscArea.hpp"
#include "graph/core/Frustum.hpp"
#include "graph/grouping/GroupingNodes.hpp"
#include "graph/lod/Lod.hpp"

#include <algorithm>
#include <bit>

namespace arcomp {

namespace {

// Runs shorter than this are tested one sphere at a time: setting up the
// four-lane test costs more than it saves on one or two spheres.
constexpr std::uint32_t kShortestRun = 4;

// The walk goes over the scene's SiblingLayout: a node's children are one
// run of slots, tested together; what the walk reads per object lies in
// flat arrays that it reads front to back.
struct SelectPass {
    World& world;
    const Scene& scene;
    const SiblingLayout& layout;
    const View& view;
    const SelectSettings& settings;
    DrawList& out;
    Frustum frustum;
    float pixelScale;
    float viewportPixels;
    glm::vec3 gaze;

    // View::projectedArea with this frame's pixel scale and the eye
    // distance the caller already has.
    float pixelsOf(float radius, float distance) const {
        return projectedDiscArea(radius, distance, pixelScale, viewportPixels);
    }

    // Visits the node in `slot` and what lies below it. Once a node lies
    // wholly inside the frustum, nothing below it is tested again. `level`
    // and `fade` come from the nearest LOD node above.
    void visit(std::uint32_t slot, bool inside, std::uint8_t level, float fade) {
        ++out.nodesVisited;
        if (!inside) {
            const Containment c = frustum.classify(layout.bound(slot));
            if (c == Containment::Outside) {
                ++out.nodesCulled;
                return;
            }
            inside = c == Containment::Inside;
        }
        visitInFrustum(slot, inside, level, fade);
    }

    // The node's children, tested as one run of spheres unless the node
    // lies inside the frustum.
    void visitChildren(std::uint32_t slot, bool inside, std::uint8_t level, float fade) {
        const std::uint32_t first = layout.firstChild[slot], end = layout.childEnd[slot];
        if (inside || end - first < kShortestRun) {
            for (std::uint32_t child = first; child < end; ++child) visit(child, inside, level, fade);
            return;
        }
        for (std::uint32_t run = first; run < end; run += Frustum::kMaxRun) {
            const std::uint32_t count = std::min(end - run, Frustum::kMaxRun);
            const RunContainment c = frustum.classifyRun(&layout.centerX[run], &layout.centerY[run],
                                                         &layout.centerZ[run], &layout.radius[run], count);
            const std::uint32_t all = count == 32 ? ~0u : (1u << count) - 1u;
            out.nodesVisited += count;
            out.nodesCulled += static_cast<std::size_t>(std::popcount(c.outside));
            for (std::uint32_t shown = all & ~c.outside; shown != 0; shown &= shown - 1) {
                const int i = std::countr_zero(shown);
                visitInFrustum(run + static_cast<std::uint32_t>(i), (c.inside >> i) & 1u, level, fade);
            }
        }
    }

    // A node found not outside the frustum: what to draw of it, and where to go from it.
    void visitInFrustum(std::uint32_t slot, bool inside, std::uint8_t level, float fade) {
        switch (layout.kind[slot]) {
        case NodeKind::Mesh:
            {
                const NodeId node = layout.node[slot];
                const Sphere bound = layout.bound(slot);
                if (world.holdouts.has(node))
                    out.holdouts.push_back({static_cast<std::uint32_t>(out.items.size()), glm::dot(bound.center - view.eye, view.forward)});
                const float distance = glm::length(bound.center - view.eye);
                out.items.push_back({node, scene.meshPart(node), distance, pixelsOf(bound.radius, distance), level,
                                     settings.shading, fade});
            }
            break;
        case NodeKind::PointCloud:
            out.pointClouds.push_back({layout.node[slot], glm::length(layout.bound(slot).center - view.eye)});
            break;
        case NodeKind::Lod:
            visitLod(slot, inside, fade);
            return;  // its children are levels: only the chosen ones are visited
        case NodeKind::Grouping:
            if (settings.grouping) {
                visitGrouping(slot, inside, level, fade);
                return;  // its children are reached through the grouping tree
            }
            break;
        case NodeKind::SilhouetteRegion:
            {
                const NodeId node = layout.node[slot];
                const Sphere bound = layout.bound(slot);
                ARCOMP_CHECK(layout.payload[slot] < world.silhouettes.nodes.size(), "a silhouette node has its entry in world.silhouettes");
                const SilhouetteNode& s = world.silhouettes.nodes[layout.payload[slot]];
                const glm::vec3 localEye = glm::vec3(glm::inverse(scene.world(node)) * glm::vec4(view.eye, 1.0f));
                const SilhouetteRange r = s.rangeFor(localEye);
                const float distance = glm::length(bound.center - view.eye);
                out.items.push_back({node, s.part, distance, pixelsOf(bound.radius, distance), level, settings.shading,
                                     fade, r.firstIndex, r.indexCount});
            }
            break;
        default:
            break;
        }
        visitChildren(slot, inside, level, fade);
    }

    void visitLod(std::uint32_t slot, bool inside, float fade) {
        if (!settings.lod) {
            visitLevel(slot, 0, inside, fade);
            return;
        }
        LodTable& lods = world.lods;
        const std::uint32_t i = layout.payload[slot];
        ARCOMP_CHECK(i < lods.size(), "an LOD node has its entry in world.lods");
        const LodNode& n = lods.node(i);
        const Sphere bound = layout.bound(slot);
        LodInputs in;
        in.distance = glm::length(bound.center - view.eye);
        if (n.policy == LodPolicy::ScreenSize || n.policy == LodPolicy::ScreenSizeTimesAcuity)
            in.pixels = in.distance > bound.radius ? 2.0f * bound.radius / in.distance * pixelScale
                                                   : static_cast<float>(view.viewport.y);
        if (n.policy == LodPolicy::GazeAcuity || n.policy == LodPolicy::ScreenSizeTimesAcuity)
            in.acuity = lods.acuity(i, scene.world(layout.node[slot]), view.eye, gaze, settings.timeSeconds);
        const LodChoice c = lods.choose(i, in, settings.timeSeconds);
        visitLevel(slot, c.level, inside, fade * c.fade);
        if (c.fadingLevel != kNoLevel) visitLevel(slot, c.fadingLevel, inside, fade * (1.0f - c.fade));
    }

    // The paper's NodeChoice over the grouping tree (DESIGN.md §2): a group
    // in view whose Ω at its eye distance is below Ωt is drawn as its proxy;
    // otherwise its two children are tried; an object is visited as a
    // subtree, so its own LOD node picks its level.
    void visitGrouping(std::uint32_t slot, bool inside, std::uint8_t level, float fade) {
        const NodeId node = layout.node[slot];
        ARCOMP_CHECK(layout.payload[slot] < world.grouping.nodes.size(), "a grouping node has its entry in world.grouping");
        GroupingNode& g = world.grouping.nodes[layout.payload[slot]];
        const GroupingTree& tree = g.tree;
        if (tree.objectCount() != g.objects.size()) return;  // not built: draws nothing rather than guess
        refreshObjectSlots(slot, g);
        if (g.proxyModel.size() < tree.nodeCount()) g.proxyModel.resize(tree.nodeCount());
        const GroupingParams& params = tree.params();
        auto& stack = g.pending;
        stack.clear();
        for (std::uint32_t r : tree.roots()) stack.push_back({r, inside});
        while (!stack.empty()) {
            auto [t, in] = stack.back();
            stack.pop_back();
            if (tree.isLeaf(t)) {
                visit(g.objectSlot[t], in, level, fade);
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
            DrawItem item{node, g.boxPart, leye, pixelsOf(s.radius, leye), level, settings.shading, fade};
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

    // Object i is the grouping node's i-th child; its slot moves when the
    // scene's structure changes.
    void refreshObjectSlots(std::uint32_t slot, GroupingNode& g) {
        bool valid = g.objectSlot.size() == g.objects.size();
        for (std::size_t i = 0; valid && i < g.objects.size(); i += std::max<std::size_t>(1, g.objects.size() / 8))
            valid = g.objectSlot[i] < layout.size() && layout.node[g.objectSlot[i]] == g.objects[i];
        if (valid) return;
        g.objectSlot.clear();
        for (std::uint32_t child = layout.firstChild[slot]; child < layout.childEnd[slot]; ++child) g.objectSlot.push_back(child);
        for (std::size_t i = 0; i < g.objects.size(); ++i)
            ARCOMP_CHECK(i < g.objectSlot.size() && layout.node[g.objectSlot[i]] == g.objects[i], "a grouping node's children do not change after buildGrouping");
    }

    // Visits the LOD node's child number `level`, or its last child when it
    // has fewer.
    void visitLevel(std::uint32_t lodSlot, std::uint8_t level, bool inside, float fade) {
        const std::uint32_t first = layout.firstChild[lodSlot], end = layout.childEnd[lodSlot];
        if (first == end) return;
        const auto shown = static_cast<std::uint8_t>(std::min<std::uint32_t>(level, end - first - 1));
        visit(first + shown, inside, shown, fade);
    }
};

} // namespace

void select(World& world, const View& view, const SelectSettings& settings, DrawList& out) {
    const Scene& scene = world.scene;
    out.clear();
    if (scene.order().empty()) return;
    const glm::vec3 gaze = glm::length(settings.gaze) > 0.0f ? glm::normalize(settings.gaze) : view.forward;
    SelectPass pass{world,
                    scene,
                    scene.siblingLayout(),
                    view,
                    settings,
                    out,
                    Frustum::fromViewProjection(view.viewProjection()),
                    view.pixelScale(),
                    static_cast<float>(view.viewport.x) * static_cast<float>(view.viewport.y),
                    gaze};
    pass.visit(0, false, 0, 1.0f);
}

} // namespace arcomp
