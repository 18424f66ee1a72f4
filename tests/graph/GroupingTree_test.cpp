#include "graph/grouping/GroupingTree.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

namespace arcomp {
namespace {

// The paper's procedure as written (Fig. 6): for each Ωt, repeatedly merge
// the pair of smallest Ω0 in T while it is below Ωt. Cubic, and the
// reference the fast build must match. Ties go to the smaller node ids, as
// in GroupingTree.
struct ReferenceTree {
    std::vector<GroupingItem> item;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> children;  // per group, from node n on
    std::vector<float> omega;
    std::set<std::uint32_t> roots;
};

ReferenceTree referenceBuild(const std::vector<GroupingItem>& objects, const GroupingParams& p) {
    ReferenceTree t;
    t.item = objects;
    std::vector<std::uint32_t> list;
    for (std::uint32_t i = 0; i < objects.size(); ++i) list.push_back(i);
    for (int k = 0; k < p.stepCount(); ++k) {
        const double threshold = p.thresholdAt(k);
        for (;;) {
            float best = 0;
            std::uint32_t bi = 0, bj = 0;
            bool any = false;
            for (std::size_t x = 0; x < list.size(); ++x)
                for (std::size_t y = x + 1; y < list.size(); ++y) {
                    const std::uint32_t i = std::min(list[x], list[y]), j = std::max(list[x], list[y]);
                    const float w = omega0(t.item[i], t.item[j], p);
                    if (!any || w < best || (w == best && (i < bi || (i == bi && j < bj)))) {
                        best = w, bi = i, bj = j;
                        any = true;
                    }
                }
            if (!any || !(double(best) < threshold)) break;
            const auto g = static_cast<std::uint32_t>(t.item.size());
            t.item.push_back(mergedItem(t.item[bi], t.item[bj]));
            t.children.push_back({bi, bj});
            t.omega.push_back(best);
            std::erase(list, bi);
            std::erase(list, bj);
            list.push_back(g);
        }
    }
    t.roots.insert(list.begin(), list.end());
    return t;
}

// Objects on a jittered plantation grid, in a few sizes and colours, so
// that many of them pass the paper's strict shape and colour terms.
std::vector<GroupingItem> randomObjects(std::size_t n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> jitter(-12.0f, 12.0f);
    std::uniform_int_distribution<int> kind(0, 2);
    std::uniform_real_distribution<float> tint(-0.03f, 0.03f);
    const glm::vec3 palette[3] = {{0.1f, 0.5f, 0.1f}, {0.15f, 0.45f, 0.1f}, {0.7f, 0.2f, 0.1f}};
    const float edges[3] = {180.0f, 200.0f, 220.0f};
    std::vector<GroupingItem> out;
    const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(double(n))));
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3 c{float(i % side) * 200.0f + jitter(rng), 0.0f, float(i / side) * 200.0f + jitter(rng)};
        const float e = edges[kind(rng)];
        const glm::vec3 h{e * 0.5f, 150.0f, e * 0.5f};
        const glm::vec3 color = palette[kind(rng)] + glm::vec3(tint(rng), tint(rng), tint(rng));
        out.push_back(groupingItem(Box{c - h + glm::vec3(0, 150, 0), c + h + glm::vec3(0, 150, 0)}, color));
    }
    return out;
}

void expectSameTree(const GroupingTree& fast, const ReferenceTree& ref, std::size_t n) {
    ASSERT_EQ(fast.nodeCount(), ref.item.size());
    for (std::size_t g = n; g < ref.item.size(); ++g) {
        const auto [a, b] = ref.children[g - n];
        const auto id = static_cast<std::uint32_t>(g);
        EXPECT_EQ(fast.left(id), a) << "group " << g;
        EXPECT_EQ(fast.right(id), b) << "group " << g;
        EXPECT_EQ(fast.mergeOmega0(id), ref.omega[g - n]) << "group " << g;
    }
    const std::set<std::uint32_t> roots(fast.roots().begin(), fast.roots().end());
    EXPECT_EQ(roots, ref.roots);
}

TEST(GroupingTree, matchesThePapersProcedureOnRandomObjects) {
    const GroupingParams p;
    for (unsigned seed : {1u, 2u, 3u}) {
        const auto objects = randomObjects(300, seed);
        GroupingTree fast;
        fast.build(objects, p);
        const ReferenceTree ref = referenceBuild(objects, p);
        EXPECT_GT(ref.children.size(), 50u) << "the scene should group";
        expectSameTree(fast, ref, objects.size());
    }
}

TEST(GroupingTree, matchesThePapersProcedureWithoutProximityOrShapeBounds) {
    // No spatial bound applies: every pair is a candidate.
    GroupingParams p;
    p.alphaP = 0.0f;
    p.alphaS = 0.0f;
    p.alphaC = 400.0f;
    const auto objects = randomObjects(120, 7);
    GroupingTree fast;
    fast.build(objects, p);
    expectSameTree(fast, referenceBuild(objects, p), objects.size());
}

// Nothing left could group, and every group's pair still passes.
void expectSettled(const GroupingTree& t) {
    const double last = t.params().lastThreshold();
    std::vector<int> owners(t.objectCount(), 0);
    for (std::uint32_t r : t.roots()) {
        EXPECT_EQ(t.parent(r), kNoGroupingNode);
        for (std::uint32_t o : t.objectsUnder(r)) ++owners[o];
    }
    for (int c : owners) EXPECT_EQ(c, 1);
    for (std::size_t x = 0; x < t.roots().size(); ++x)
        for (std::size_t y = x + 1; y < t.roots().size(); ++y)
            EXPECT_GE(double(omega0(t.item(t.roots()[x]), t.item(t.roots()[y]), t.params())), last);
    for (std::uint32_t n = 0; n < t.nodeCount(); ++n) {
        if (t.alive(n) && !t.isLeaf(n)) {
            EXPECT_LT(double(t.mergeOmega0(n)), last);
        }
    }
}

Box shifted(const Box& b, glm::vec3 d) { return {b.min + d, b.max + d}; }

TEST(GroupingTree, objectsMovingTogetherStayInTheirGroup) {
    const GroupingParams p;
    const auto objects = randomObjects(200, 4);
    GroupingTree t;
    t.build(objects, p);
    // The largest group moves as one (common motion: Ff = 0).
    std::uint32_t biggest = t.roots()[0];
    for (std::uint32_t r : t.roots())
        if (t.objectsUnder(r).size() > t.objectsUnder(biggest).size()) biggest = r;
    const auto members = t.objectsUnder(biggest);
    ASSERT_GT(members.size(), 4u);
    const std::uint32_t left = t.left(biggest), right = t.right(biggest);
    const glm::vec3 v{30.0f, 0.0f, 0.0f};
    for (std::uint32_t o : members) t.moveObject(o, shifted(t.item(o).box, v * 0.1f), v);
    const GroupingRebuildStats s = t.rebuildMoved();
    EXPECT_EQ(s.dissolved, 0u);
    EXPECT_TRUE(t.alive(biggest));
    EXPECT_EQ(t.left(biggest), left);
    EXPECT_EQ(t.right(biggest), right);
    EXPECT_EQ(t.objectsUnder(biggest).size(), members.size());
    expectSettled(t);
}

TEST(GroupingTree, anObjectLeavingItsGroupIsRegroupedLocally) {
    const GroupingParams p;
    const auto objects = randomObjects(200, 5);
    GroupingTree t;
    t.build(objects, p);
    std::uint32_t grouped = 0;
    while (t.parent(grouped) == kNoGroupingNode) ++grouped;
    // Remember a group not above it: it must be left as it is.
    std::set<std::uint32_t> above;
    for (std::uint32_t g = t.parent(grouped); g != kNoGroupingNode; g = t.parent(g)) above.insert(g);
    std::uint32_t untouched = kNoGroupingNode;
    for (std::uint32_t r : t.roots())
        if (!t.isLeaf(r) && !above.count(r)) untouched = r;
    ASSERT_NE(untouched, kNoGroupingNode);
    const auto untouchedLeft = t.left(untouched);

    t.moveObject(grouped, shifted(t.item(grouped).box, {0.0f, 0.0f, 90000.0f}), {0.0f, 0.0f, 500.0f});
    const GroupingRebuildStats s = t.rebuildMoved();
    EXPECT_GT(s.dissolved, 0u);
    EXPECT_EQ(t.parent(grouped), kNoGroupingNode) << "far away and fast, it groups with nothing";
    EXPECT_TRUE(t.alive(untouched));
    EXPECT_EQ(t.left(untouched), untouchedLeft);
    expectSettled(t);
}

TEST(GroupingTree, manyMovesKeepTheTreeSettled) {
    const GroupingParams p;
    const auto objects = randomObjects(250, 6);
    GroupingTree t;
    t.build(objects, p);
    std::mt19937 rng(9);
    std::uniform_int_distribution<std::uint32_t> pick(0, 249);
    std::uniform_real_distribution<float> step(-60.0f, 60.0f);
    for (int frame = 0; frame < 20; ++frame) {
        for (int k = 0; k < 5; ++k) {
            const std::uint32_t o = pick(rng);
            const glm::vec3 d{step(rng), 0.0f, step(rng)};
            t.moveObject(o, shifted(t.item(o).box, d), d * 10.0f);
        }
        t.rebuildMoved();
    }
    expectSettled(t);
}

}  // namespace
}  // namespace arcomp

namespace arcomp {
namespace {

// Many objects drifting apart in one frame: cuts free subtrees whose own
// top then breaks too, before they are back at the top level.
TEST(GroupingTree, cascadingCutsInOneRebuildKeepTheTreeSettled) {
    const GroupingParams p;
    const auto objects = randomObjects(400, 11);
    GroupingTree t;
    t.build(objects, p);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> step(-150.0f, 150.0f);
    for (int frame = 0; frame < 30; ++frame) {
        for (std::uint32_t o = 0; o < 400; o += 3) {
            const glm::vec3 d{step(rng), 0.0f, step(rng)};
            t.moveObject(o, shifted(t.item(o).box, d), d * 30.0f);
        }
        t.rebuildMoved();
    }
    expectSettled(t);
}

}  // namespace
}  // namespace arcomp
