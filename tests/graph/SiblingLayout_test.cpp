// The select pass's copy of the scene (graph/core/SiblingLayout.hpp) says
// what the scene says, after every kind of change, and the select pass over
// it draws what the straightforward walk over the scene's nodes draws.
#include "graph/core/Frustum.hpp"
#include "graph/core/SelectPass.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <random>
#include <vector>

using namespace arcomp;

namespace {

// A random scene: groups, transforms (some scaled), meshes, empty groups,
// and LOD nodes under distance or screen-size policies, with or without
// hysteresis and cross-fades, whose levels are meshes or whole subtrees.
// The same seed builds the same scene.
struct RandomScene {
    World world;
    Scene& scene = world.scene;
    std::mt19937 random;
    std::vector<NodeId> transforms;
    std::vector<MeshPart> parts;

    explicit RandomScene(unsigned seed) : random(seed) {
        const std::uint32_t material = scene.addMaterial({});
        parts = {{scene.addGeometry(makeUvSphere(1.0f, 8, 4)), material},
                 {scene.addGeometry(makeBox({2.0f, 0.5f, 1.0f})), material}};
        grow(scene.root(), 3, 12);
        scene.update();
    }

    float uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(random); }
    int pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(random); }

    glm::mat4 randomLocal() {
        glm::mat4 m = glm::translate(glm::mat4(1.0f), {uniform(-40, 40), uniform(-5, 5), uniform(-40, 40)});
        if (pick(0, 3) == 0) m = glm::scale(m, glm::vec3(uniform(0.3f, 3.0f)));
        return m;
    }

    NodeId addMesh(NodeId parent) { return scene.addMesh(parent, parts[static_cast<std::size_t>(pick(0, 1))]); }

    void grow(NodeId parent, int depth, int children) {
        for (int i = 0; i < children; ++i) {
            switch (depth > 0 ? pick(0, 4) : 0) {
            case 0: addMesh(parent); break;
            case 1: scene.addGroup(parent); break;  // empty: an empty bound
            case 2: {
                const NodeId t = scene.addTransform(parent, randomLocal());
                transforms.push_back(t);
                grow(t, depth - 1, pick(1, 6));
            } break;
            case 3: grow(scene.addGroup(parent), depth - 1, pick(1, 40)); break;
            default: addLod(parent, depth); break;
            }
        }
    }

    void addLod(NodeId parent, int depth) {
        LodNode lod;
        if (pick(0, 1) == 0) {
            lod.policy = LodPolicy::Distance;
            lod.setThresholds({uniform(5, 30), uniform(30, 80)});
        } else {
            lod.policy = LodPolicy::ScreenSize;
            lod.setThresholds({uniform(60, 200), uniform(5, 60)});
        }
        lod.hysteresis = pick(0, 1) == 0 ? 0.0f : 0.2f;
        lod.fadeSeconds = pick(0, 1) == 0 ? 0.0f : 0.5f;
        const NodeId t = scene.addTransform(parent, randomLocal());
        transforms.push_back(t);
        const NodeId node = scene.addNode(t, NodeKind::Lod, world.lods.add(lod));
        const int levels = pick(1, 4);  // fewer than three: the last level stands in
        for (int level = 0; level < levels; ++level) {
            if (level == 1 && depth > 1)
                grow(scene.addGroup(node), depth - 2, pick(1, 5));
            else
                addMesh(node);
        }
    }
};

// A transform or group with one child and no bound of its own shares that
// child's slot, unless a grouping node's tree names it.
bool passesThrough(const Scene& scene, NodeId n) {
    const NodeKind k = scene.kind(n);
    const NodeId parent = scene.parent(n);
    return (k == NodeKind::Transform || k == NodeKind::Group) && scene.children(n).size() == 1 &&
           scene.localBound(n).empty() && (parent == kNoNode || scene.kind(parent) != NodeKind::Grouping);
}

// The node whose slot stands for n: n, or the end of its pass-through chain.
NodeId slotHolder(const Scene& scene, NodeId n) {
    while (passesThrough(scene, n)) n = scene.children(n).front();
    return n;
}

void expectLayoutMatchesScene(const Scene& scene) {
    const SiblingLayout& layout = scene.siblingLayout();
    std::size_t holders = 0;
    for (const NodeId n : scene.order()) {
        const std::uint32_t slot = layout.slotOf[n];
        ASSERT_LT(slot, layout.size());
        const NodeId holder = n == scene.root() ? n : slotHolder(scene, n);
        EXPECT_EQ(layout.slots[slot].node, holder) << "node " << n;
        // Shared or not, the slot's bound is the node's.
        const Sphere a = layout.bound(slot), b = scene.worldBound(n);
        EXPECT_EQ(a.center, b.center) << "node " << n;
        EXPECT_EQ(a.radius, b.radius) << "node " << n;
        // The copy that runs of siblings are culled from.
        EXPECT_EQ(glm::vec3(layout.centerX[slot], layout.centerY[slot], layout.centerZ[slot]), b.center)
            << "node " << n;
        EXPECT_EQ(layout.radius[slot], b.radius) << "node " << n;
        if (holder != n) continue;
        ++holders;
        EXPECT_EQ(layout.slots[slot].kind, scene.kind(n));
        EXPECT_EQ(layout.slots[slot].payload, scene.payload(n));
        std::vector<NodeId> children, expected;
        for (std::uint32_t c = layout.slots[slot].firstChild; c < layout.childEnd(slot); ++c)
            children.push_back(layout.slots[c].node);
        for (const NodeId c : scene.children(n))
            expected.push_back(scene.kind(n) == NodeKind::Grouping ? c : slotHolder(scene, c));
        EXPECT_EQ(children, expected) << "node " << n;
    }
    EXPECT_EQ(layout.size(), holders);
}

// The select pass as it would be written without a layout: recursion over
// the scene's NodeIds, one sphere test per node.
struct StraightforwardWalk {
    World& world;
    const View& view;
    const SelectSettings& settings;
    DrawList& out;
    Frustum frustum = Frustum::fromViewProjection(view.viewProjection());

    void visit(NodeId n, bool inside, std::uint8_t level, float fade) {
        const Scene& scene = world.scene;
        // The layout's walk does not stop at a pass-through node: it tests
        // the same bound at the node that holds the slot, and counts that.
        const bool counted = n == scene.root() || !passesThrough(scene, n);
        if (counted) ++out.nodesVisited;
        const Sphere& bound = scene.worldBound(n);
        if (!inside) {
            const Containment c = frustum.classify(bound);
            if (c == Containment::Outside) {
                if (!counted) ++out.nodesVisited;
                ++out.nodesCulled;
                return;
            }
            inside = c == Containment::Inside;
        }
        const std::vector<NodeId> children = scene.children(n);
        if (scene.kind(n) == NodeKind::Lod) {
            LodInputs in;
            in.distance = glm::length(bound.center - view.eye);
            in.pixels = in.distance > bound.radius ? 2.0f * bound.radius / in.distance * view.pixelScale()
                                                   : static_cast<float>(view.viewport.y);
            const LodChoice c = world.lods.choose(scene.payload(n), in, settings.timeSeconds);
            const auto visitLevel = [&](std::uint8_t l, float f) {
                if (children.empty()) return;
                const auto shown = static_cast<std::uint8_t>(std::min<std::size_t>(l, children.size() - 1));
                visit(children[shown], inside, shown, f);
            };
            visitLevel(c.level, fade * c.fade);
            if (c.fadingLevel != kNoLevel) visitLevel(c.fadingLevel, fade * (1.0f - c.fade));
            return;
        }
        if (scene.kind(n) == NodeKind::Mesh)
            out.items.push_back({n, scene.meshPart(n), glm::length(bound.center - view.eye), view.projectedArea(bound),
                                 level, settings.shading, fade});
        for (const NodeId c : children) visit(c, inside, level, fade);
    }
};

void expectSameDrawLists(const DrawList& a, const DrawList& b) {
    ASSERT_EQ(a.items.size(), b.items.size());
    for (std::size_t i = 0; i < a.items.size(); ++i) {
        EXPECT_EQ(a.items[i].node, b.items[i].node) << "item " << i;
        EXPECT_EQ(a.items[i].part.geometry, b.items[i].part.geometry) << "item " << i;
        EXPECT_EQ(a.items[i].level, b.items[i].level) << "item " << i;
        EXPECT_EQ(a.items[i].fade, b.items[i].fade) << "item " << i;
        EXPECT_EQ(a.items[i].viewDistance, b.items[i].viewDistance) << "item " << i;
        EXPECT_EQ(a.items[i].screenArea, b.items[i].screenArea) << "item " << i;
    }
    EXPECT_EQ(a.nodesVisited, b.nodesVisited);
    EXPECT_EQ(a.nodesCulled, b.nodesCulled);
}

View randomView(std::mt19937& random) {
    std::uniform_real_distribution<float> coordinate(-60.0f, 60.0f);
    const glm::vec3 eye{coordinate(random), coordinate(random) * 0.2f, coordinate(random)};
    const glm::vec3 target{coordinate(random), 0.0f, coordinate(random)};
    return View::lookAt(eye, target, {0, 1, 0}, 60.0f, {1280, 720}, 0.1f, 200.0f);
}

}  // namespace

TEST(SiblingLayout, matchesTheSceneAfterUpdate) {
    RandomScene s(1);
    expectLayoutMatchesScene(s.scene);
}

TEST(SiblingLayout, followsMovedTransformsAfterSetLocal) {
    RandomScene s(2);
    ASSERT_FALSE(s.transforms.empty());
    for (std::size_t i = 0; i < s.transforms.size(); i += 3) s.scene.setLocal(s.transforms[i], s.randomLocal());
    s.scene.update();
    expectLayoutMatchesScene(s.scene);
}

TEST(SiblingLayout, followsNodesAddedAfterTheFirstUpdate) {
    RandomScene s(3);
    s.grow(s.transforms.front(), 2, 5);
    s.grow(s.scene.root(), 1, 7);
    s.scene.update();
    expectLayoutMatchesScene(s.scene);
}

TEST(SiblingLayout, givesEachNodesChildrenOneRunOfSlots) {
    World world;
    Scene& scene = world.scene;
    const NodeId a = scene.addGroup(scene.root());
    const NodeId b = scene.addGroup(scene.root());
    const NodeId a1 = scene.addGroup(a);
    const NodeId b1 = scene.addGroup(b);
    const NodeId a2 = scene.addGroup(a);  // added after b's child, still beside a1
    scene.update();
    const SiblingLayout& layout = scene.siblingLayout();
    EXPECT_EQ(layout.slotOf[a2], layout.slotOf[a1] + 1);
    EXPECT_EQ(layout.slots[layout.slotOf[a]].firstChild, layout.slotOf[a1]);
    EXPECT_EQ(layout.childEnd(layout.slotOf[a]), layout.slotOf[a2] + 1);
    // b, with one child, is a pass-through: b1 holds its slot.
    EXPECT_EQ(layout.slotOf[b], layout.slotOf[b1]);
    EXPECT_EQ(layout.slots[layout.slotOf[b]].node, b1);
}

TEST(SelectPass, drawsWhatTheStraightforwardWalkDrawsOnRandomScenes) {
    for (unsigned seed = 10; seed < 16; ++seed) {
        RandomScene ours(seed), reference(seed);
        std::mt19937 views(seed);
        DrawList fast, slow;
        std::size_t culled = 0, drawn = 0, coarse = 0;
        for (int frame = 0; frame < 30; ++frame) {
            if (frame == 15) {  // a change of structure halfway, then moves
                ours.grow(ours.scene.root(), 2, 6);
                reference.grow(reference.scene.root(), 2, 6);
            }
            if (frame >= 15) {
                const glm::mat4 local = ours.randomLocal();
                const NodeId moved = ours.transforms[static_cast<std::size_t>(frame) % ours.transforms.size()];
                ours.scene.setLocal(moved, local);
                reference.scene.setLocal(moved, local);
            }
            ours.scene.update();
            reference.scene.update();
            const View view = randomView(views);
            const SelectSettings settings{.timeSeconds = frame / 30.0};
            select(ours.world, view, settings, fast);
            slow.clear();
            StraightforwardWalk{reference.world, view, settings, slow}.visit(reference.scene.root(), false, 0, 1.0f);
            SCOPED_TRACE(testing::Message() << "seed " << seed << ", frame " << frame);
            expectSameDrawLists(fast, slow);
            culled += slow.nodesCulled;
            drawn += slow.items.size();
            for (const DrawItem& item : slow.items) coarse += item.level > 0 ? 1 : 0;
        }
        // The views cull, draw and pick coarser levels, so each was compared.
        EXPECT_GT(culled, 0u) << "seed " << seed;
        EXPECT_GT(drawn, 0u) << "seed " << seed;
        EXPECT_GT(coarse, 0u) << "seed " << seed;
    }
}

TEST(SiblingLayout, aTransformSharesItsOnlyChildsSlotUntilItHasABoundOfItsOwn) {
    World world;
    Scene& scene = world.scene;
    const MeshPart part{scene.addGeometry(makeUvSphere(1.0f, 8, 4)), scene.addMaterial({})};
    const NodeId t = scene.addTransform(scene.root(), glm::translate(glm::mat4(1.0f), {5, 0, 0}));
    const NodeId mesh = scene.addMesh(t, part);
    scene.update();
    const SiblingLayout& layout = scene.siblingLayout();
    EXPECT_EQ(layout.size(), 2u);  // the root, and the mesh in the transform's place
    EXPECT_EQ(layout.slotOf[t], layout.slotOf[mesh]);
    EXPECT_EQ(layout.slots[layout.slotOf[t]].node, mesh);

    // A bound larger than the mesh's: culling by the mesh's alone would be wrong.
    scene.setLocalBound(t, {glm::vec3(0.0f), 10.0f});
    scene.update();
    ASSERT_EQ(layout.size(), 3u);
    const std::uint32_t slot = layout.slotOf[t];
    EXPECT_EQ(layout.slots[slot].node, t);
    EXPECT_EQ(layout.bound(slot).radius, 10.0f);
    EXPECT_EQ(layout.slots[slot].childCount, 1u);
    EXPECT_EQ(layout.slots[layout.slots[slot].firstChild].node, mesh);
    expectLayoutMatchesScene(scene);
}
