#include "graph/core/SelectPass.hpp"
#include "graph/core/Check.hpp"

#include "graph/core/DiscArea.hpp"
#include "graph/core/Frustum.hpp"
#include "graph/grouping/GroupingNodes.hpp"
#include "graph/lod/Lod.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace arcomp {

namespace {

// Runs shorter than this are tested one sphere at a time: setting up the
// eight-lane test costs more than it saves on one or two spheres.
constexpr std::uint32_t kShortestRun = 4;

// The walk goes over the scene's SiblingLayout: a node's children are one
// run of slots, tested together from flat arrays of bounds; what the walk
// reads of a node it goes into is that node's one Slot record.
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

    // A bound's eye distance and View::projectedArea, with this frame's
    // pixel scale.
    struct OnScreen {
        float distance, pixels;
    };
    OnScreen onScreen(const Sphere& s) const {
        const glm::vec3 toCenter = s.center - view.eye;
        const float distanceSquared = glm::dot(toCenter, toCenter);
        return {std::sqrt(distanceSquared), projectedDiscArea(s.radius, distanceSquared, pixelScale, viewportPixels)};
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
        const std::uint32_t first = layout.slots[slot].firstChild, end = layout.childEnd(slot);
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
        const SiblingLayout::Slot& s = layout.slots[slot];
        switch (s.kind) {
        case NodeKind::Mesh: addMesh(s, level, fade); break;
        case NodeKind::PointCloud: out.pointClouds.push_back({s.node, glm::length(s.bound.center - view.eye)}); break;
        case NodeKind::Lod:
            visitLod(slot, inside, fade);
            return;  // its children are levels: only the chosen ones are visited
        case NodeKind::Grouping:
            if (settings.grouping) {
                visitGrouping(slot, inside, level, fade);
                return;  // its children are reached through the grouping tree
            }
            break;
        case NodeKind::SilhouetteRegion: addSilhouetteRegion(s, level, fade); break;
        default: break;
        }
        // One child (a transform over an object): a jump, not a loop.
        if (s.childCount == 1) return visit(s.firstChild, inside, level, fade);
        if (s.childCount != 0) visitChildren(slot, inside, level, fade);
    }

    void addMesh(const SiblingLayout::Slot& s, std::uint8_t level, float fade) {
        if (world.holdouts.has(s.node))
            out.holdouts.push_back(
                {static_cast<std::uint32_t>(out.items.size()), glm::dot(s.bound.center - view.eye, view.forward)});
        // Filled where it lies: a copy built beside it first stalls on
        // forwarding its small stores to the copy's wide loads.
        DrawItem& item = out.items.emplace_back();
        item.node = s.node;
        item.part = scene.meshPartAt(s.payload);
        const OnScreen seen = onScreen(s.bound);
        item.viewDistance = seen.distance;
        item.screenArea = seen.pixels;
        item.level = level;
        item.shading = settings.shading;
        item.fade = fade;
    }

    // Rare next to meshes, and kept out of the walk's code so that its
    // common path stays short.
    [[gnu::noinline]] void addSilhouetteRegion(const SiblingLayout::Slot& s, std::uint8_t level, float fade) {
        ARCOMP_CHECK(s.payload < world.silhouettes.nodes.size(),
                     "a silhouette node has its entry in world.silhouettes");
        const SilhouetteNode& silhouette = world.silhouettes.nodes[s.payload];
        const glm::vec3 localEye = glm::vec3(glm::inverse(scene.world(s.node)) * glm::vec4(view.eye, 1.0f));
        const SilhouetteRange r = silhouette.rangeFor(localEye);
        const OnScreen seen = onScreen(s.bound);
        out.items.push_back({s.node, silhouette.part, seen.distance, seen.pixels, level, settings.shading, fade,
                             r.firstIndex, r.indexCount});
    }

    void visitLod(std::uint32_t slot, bool inside, float fade) {
        if (!settings.lod) {
            visitLevel(slot, 0, inside, fade);
            return;
        }
        LodTable& lods = world.lods;
        const SiblingLayout::Slot& s = layout.slots[slot];
        const std::uint32_t i = s.payload;
        ARCOMP_CHECK(i < lods.size(), "an LOD node has its entry in world.lods");
        const LodRule& n = lods.rule(i);
        const Sphere& bound = s.bound;
        LodInputs in;
        in.distance = glm::length(bound.center - view.eye);
        if (n.policy == LodPolicy::ScreenSize || n.policy == LodPolicy::ScreenSizeTimesAcuity)
            in.pixels = in.distance > bound.radius ? 2.0f * bound.radius / in.distance * pixelScale
                                                   : static_cast<float>(view.viewport.y);
        if (n.policy == LodPolicy::GazeAcuity || n.policy == LodPolicy::ScreenSizeTimesAcuity)
            in.acuity = lods.acuity(i, scene.world(s.node), view.eye, gaze, settings.timeSeconds);
        const LodChoice c = lods.choose(i, in, settings.timeSeconds);
        visitLevel(slot, c.level, inside, fade * c.fade);
        if (c.fadingLevel != kNoLevel) visitLevel(slot, c.fadingLevel, inside, fade * (1.0f - c.fade));
    }

    // The paper's NodeChoice over the grouping tree (DESIGN.md §2): a group
    // in view whose Ω at its eye distance is below Ωt is drawn as its proxy;
    // otherwise its two children are tried; an object is visited as a
    // subtree, so its own LOD node picks its level.
    [[gnu::noinline]] void visitGrouping(std::uint32_t slot, bool inside, std::uint8_t level, float fade) {
        const NodeId node = layout.slots[slot].node;
        ARCOMP_CHECK(layout.slots[slot].payload < world.grouping.nodes.size(),
                     "a grouping node has its entry in world.grouping");
        GroupingNode& g = world.grouping.nodes[layout.slots[slot].payload];
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
            const OnScreen seen = onScreen(s);
            if (omegaAt(tree.mergeOmega0(t), seen.distance, params) >= g.omegaT) {
                stack.push_back({tree.right(t), in});
                stack.push_back({tree.left(t), in});
                continue;
            }
            DrawItem item{node, g.boxPart, seen.distance, seen.pixels, level, settings.shading, fade};
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
            valid = g.objectSlot[i] < layout.size() && layout.slots[g.objectSlot[i]].node == g.objects[i];
        if (valid) return;
        g.objectSlot.clear();
        for (std::uint32_t child = layout.slots[slot].firstChild; child < layout.childEnd(slot); ++child)
            g.objectSlot.push_back(child);
        for (std::size_t i = 0; i < g.objects.size(); ++i)
            ARCOMP_CHECK(i < g.objectSlot.size() && layout.slots[g.objectSlot[i]].node == g.objects[i],
                         "a grouping node's children do not change after buildGrouping");
    }

    // Visits the LOD node's child number `level`, or its last child when it
    // has fewer.
    void visitLevel(std::uint32_t lodSlot, std::uint8_t level, bool inside, float fade) {
        const SiblingLayout::Slot& lod = layout.slots[lodSlot];
        if (lod.childCount == 0) return;
        const auto shown = static_cast<std::uint8_t>(std::min<std::uint32_t>(level, lod.childCount - 1));
        const std::uint32_t child = lod.firstChild + shown;
        const SiblingLayout::Slot& s = layout.slots[child];
        if (s.kind != NodeKind::Mesh || s.childCount != 0) return visit(child, inside, shown, fade);
        // A level that is one mesh, the common case: its item, without the walk's general step.
        ++out.nodesVisited;
        if (!inside && frustum.classify(s.bound) == Containment::Outside) {
            ++out.nodesCulled;
            return;
        }
        addMesh(s, shown, fade);
    }
};

}  // namespace

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
    applyOpacity(scene, world.opacity, out);
}

}  // namespace arcomp
