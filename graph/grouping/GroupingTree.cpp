#include "graph/grouping/GroupingTree.hpp"
#include "graph/core/Check.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace arcomp {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr std::uint64_t kUnbounded = ~std::uint64_t{0};
// Reaches are bounds derived on real numbers; Ω0 is computed in float.
constexpr float kSlack = 1.01f;

}  // namespace

std::uint32_t GroupingTree::addNode(const GroupingItem& item) {
    std::uint32_t n;
    if (!freeNodes_.empty()) {
        n = freeNodes_.back();
        freeNodes_.pop_back();
        item_[n] = item;
        hot_[n].bound = sphereAround(item.box);
    } else {
        n = static_cast<std::uint32_t>(item_.size());
        item_.push_back(item);
        hot_.push_back({sphereAround(item.box), 0.0f, kNoGroupingNode, kNoGroupingNode});
        parent_.push_back(kNoGroupingNode);
        alive_.push_back(1);
        rootSlot_.push_back(kNoGroupingNode);
        cell_.push_back(kUnbounded);
        reach_.emplace_back(0.0f);
        levelSlot_.push_back(kNoGroupingNode);
    }
    hot_[n].left = hot_[n].right = parent_[n] = kNoGroupingNode;
    hot_[n].omega0 = 0.0f;
    alive_[n] = 1;
    return n;
}

void GroupingTree::makeRoot(std::uint32_t n) {
    rootSlot_[n] = static_cast<std::uint32_t>(roots_.size());
    roots_.push_back(n);
    gridInsert(n);
}

void GroupingTree::dropRoot(std::uint32_t n) {
    gridErase(n);
    const std::uint32_t slot = rootSlot_[n];
    roots_[slot] = roots_.back();
    rootSlot_[roots_[slot]] = slot;
    roots_.pop_back();
    rootSlot_[n] = kNoGroupingNode;
}

glm::vec2 GroupingTree::reach(std::uint32_t n) const {
    const glm::vec3 s = item_[n].box.size();
    const float p = proximityReach_;
    float rx = p, rz = p;
    // The shape bound needs the pair's enclosing box to have volume, which a
    // flat item cannot promise; its reach then comes from proximity alone.
    if (shapeFactor_ > 0.0f && s.y > 0.0f && s.z > 0.0f) rx = std::min(p, shapeFactor_ * s.x * kSlack);
    if (shapeFactor_ > 0.0f && s.y > 0.0f && s.x > 0.0f) rz = std::min(p, shapeFactor_ * s.z * kSlack);
    return {rx, rz};
}

int GroupingTree::levelFor(std::uint32_t n) const {
    const glm::vec2 r = reach_[n];
    const float need = 2.0f * std::max(r.x, r.y);
    if (!std::isfinite(need)) return -1;
    float c = cellSize_;
    for (int level = 0; level < kLevels; ++level, c *= 2.0f)
        if (c >= need) return level;
    return -1;
}

std::int64_t GroupingTree::cellIndex(int level, float x) const {
    return static_cast<std::int64_t>(std::floor(double(x) / levelCell_[static_cast<std::size_t>(level)]));
}

std::uint64_t GroupingTree::cellKey(int level, std::int64_t ix, std::int64_t iz) {
    constexpr std::uint64_t mask = (std::uint64_t{1} << 29) - 1;
    // Far-apart cells may share a key; that only offers extra candidates.
    return (std::uint64_t(level) << 58) | ((std::uint64_t(ix) & mask) << 29) | (std::uint64_t(iz) & mask);
}

void GroupingTree::gridInsert(std::uint32_t n) {
    reach_[n] = reach(n);
    const int level = levelFor(n);
    if (level < 0) {
        cell_[n] = kUnbounded;
        unbounded_.push_back(n);
        return;
    }
    const glm::vec3 c = item_[n].box.center();
    const std::uint64_t key = cellKey(level, cellIndex(level, c.x), cellIndex(level, c.z));
    cell_[n] = key;
    grid_[key].push_back(n);
    auto& items = levelItems_[static_cast<std::size_t>(level)];
    levelSlot_[n] = static_cast<std::uint32_t>(items.size());
    items.push_back(n);
}

void GroupingTree::gridErase(std::uint32_t n) {
    std::vector<std::uint32_t>* list = &unbounded_;
    if (cell_[n] != kUnbounded) {
        list = &grid_[cell_[n]];
        auto& items = levelItems_[static_cast<std::size_t>(cell_[n] >> 58)];
        const std::uint32_t slot = levelSlot_[n];
        items[slot] = items.back();
        levelSlot_[items[slot]] = slot;
        items.pop_back();
    }
    const auto it = std::find(list->begin(), list->end(), n);
    ARCOMP_CHECK(it != list->end(), "roots are always in the grid");
    *it = list->back();
    list->pop_back();
    if (list->empty() && cell_[n] != kUnbounded) grid_.erase(cell_[n]);
    cell_[n] = kUnbounded;
}

void GroupingTree::pushCandidate(std::uint32_t a, std::uint32_t b, float omega) {
    heap_.push_back({omega, std::min(a, b), std::max(a, b)});
    std::push_heap(heap_.begin(), heap_.end(), std::greater<>{});
}

void GroupingTree::consider(std::uint32_t n, std::uint32_t other, bool onlyLater) {
    if (other == n || (onlyLater && other < n)) return;
    const glm::vec3 d = item_[n].box.center() - item_[other].box.center();
    const glm::vec2 r = reach_[n] + reach_[other];
    if (std::abs(d.x) > r.x || std::abs(d.z) > r.y) return;
    const std::uint32_t a = std::min(n, other), b = std::max(n, other);
    const float w = omega0(item_[a], item_[b], params_);
    if (double(w) < lastThreshold_) pushCandidate(a, b, w);
}

void GroupingTree::offerPairs(std::uint32_t n, bool onlyLater) {
    const glm::vec2 r = reach_[n];
    const glm::vec3 c = item_[n].box.center();
    if (cell_[n] == kUnbounded) {
        for (std::uint32_t other : roots_) consider(n, other, onlyLater);
        return;
    }
    for (int level = 0; level < kLevels; ++level) {
        const auto& items = levelItems_[static_cast<std::size_t>(level)];
        if (items.empty()) continue;
        const double size = levelCell_[static_cast<std::size_t>(level)];
        // Roots at this level reach at most half a cell.
        const double mx = double(r.x) + size * 0.5, mz = double(r.y) + size * 0.5;
        const auto x0 = static_cast<std::int64_t>(std::floor((double(c.x) - mx) / size));
        const auto x1 = static_cast<std::int64_t>(std::floor((double(c.x) + mx) / size));
        const auto z0 = static_cast<std::int64_t>(std::floor((double(c.z) - mz) / size));
        const auto z1 = static_cast<std::int64_t>(std::floor((double(c.z) + mz) / size));
        // A cell costs a hash lookup, a root a few comparisons: a wide reach
        // over a sparse level is cheaper served by the level's list.
        if (double(x1 - x0 + 1) * double(z1 - z0 + 1) * 4.0 > double(items.size())) {
            for (std::uint32_t other : items) consider(n, other, onlyLater);
            continue;
        }
        for (std::int64_t ix = x0; ix <= x1; ++ix)
            for (std::int64_t iz = z0; iz <= z1; ++iz) {
                const auto it = grid_.find(cellKey(level, ix, iz));
                if (it == grid_.end()) continue;
                for (std::uint32_t other : it->second) consider(n, other, onlyLater);
            }
    }
    for (std::uint32_t other : unbounded_) consider(n, other, onlyLater);
}

void GroupingTree::agglomerate(GroupingRebuildStats* stats) {
    while (!heap_.empty()) {
        std::pop_heap(heap_.begin(), heap_.end(), std::greater<>{});
        const Candidate top = heap_.back();
        heap_.pop_back();
        if (rootSlot_[top.a] == kNoGroupingNode || rootSlot_[top.b] == kNoGroupingNode) continue;
        // Every live pair below the last Ωt is in the heap, so the smallest
        // left decides: nothing more groups.
        if (!(double(top.omega) < lastThreshold_)) break;
        const GroupingItem merged = mergedItem(item_[top.a], item_[top.b]);
        dropRoot(top.a);
        dropRoot(top.b);
        const std::uint32_t g = addNode(merged);
        hot_[g].left = top.a;
        hot_[g].right = top.b;
        hot_[g].omega0 = top.omega;
        parent_[top.a] = parent_[top.b] = g;
        makeRoot(g);
        offerPairs(g, false);
        if (stats) ++stats->merged;
    }
    heap_.clear();
}

void GroupingTree::build(std::span<const GroupingItem> objects, const GroupingParams& params) {
    params_ = params;
    lastThreshold_ = params.lastThreshold();
    objectCount_ = objects.size();
    item_.clear();
    hot_.clear();
    parent_.clear();
    alive_.clear();
    roots_.clear();
    rootSlot_.clear();
    cell_.clear();
    reach_.clear();
    unbounded_.clear();
    freeNodes_.clear();
    heap_.clear();
    grid_.clear();
    for (auto& items : levelItems_) items.clear();
    levelSlot_.clear();
    movedObjects_.clear();
    moved_.assign(objects.size(), 0);

    const double limit = lastThreshold_ * double(params.l0);
    proximityReach_ = params.alphaP > 0.0f ? float(limit / double(params.alphaP)) * kSlack : kInf;
    // Ms < q = Ωt·L0/αs caps the enclosing box at (V1 + V2)/(1 - q), which
    // caps the centres' distance per axis at (1/(1 - q) - 1/2) times the
    // sum of the two extents.
    const double q = params.alphaS > 0.0f ? limit / double(params.alphaS) : 1.0;
    shapeFactor_ = q < 1.0 ? float(1.0 / (1.0 - q) - 0.5) : 0.0f;

    for (const GroupingItem& o : objects) addNode(o);
    std::vector<float> reaches;
    reaches.reserve(objects.size());
    for (std::uint32_t n = 0; n < objects.size(); ++n) {
        const glm::vec2 r = reach(n);
        const float m = 2.0f * std::max(r.x, r.y);
        if (std::isfinite(m) && m > 0.0f) reaches.push_back(m);
    }
    cellSize_ = 1.0f;
    if (!reaches.empty()) {
        std::nth_element(reaches.begin(), reaches.begin() + std::ptrdiff_t(reaches.size() / 2), reaches.end());
        cellSize_ = reaches[reaches.size() / 2];
    }
    for (int level = 0; level < kLevels; ++level)
        levelCell_[static_cast<std::size_t>(level)] = double(cellSize_) * std::ldexp(1.0, level);
    for (std::uint32_t n = 0; n < objects.size(); ++n) makeRoot(n);
    for (std::uint32_t n = 0; n < objects.size(); ++n) offerPairs(n, true);
    agglomerate(nullptr);
}

std::size_t GroupingTree::depth() const {
    std::size_t best = 0;
    std::vector<std::pair<std::uint32_t, std::size_t>> stack;
    for (std::uint32_t r : roots_) stack.push_back({r, 1});
    while (!stack.empty()) {
        const auto [n, d] = stack.back();
        stack.pop_back();
        best = std::max(best, d);
        if (!isLeaf(n)) {
            stack.push_back({hot_[n].left, d + 1});
            stack.push_back({hot_[n].right, d + 1});
        }
    }
    return best;
}

std::vector<std::uint32_t> GroupingTree::objectsUnder(std::uint32_t n) const {
    std::vector<std::uint32_t> out, stack{n};
    while (!stack.empty()) {
        const std::uint32_t m = stack.back();
        stack.pop_back();
        if (isLeaf(m))
            out.push_back(m);
        else {
            stack.push_back(hot_[m].left);
            stack.push_back(hot_[m].right);
        }
    }
    return out;
}

void GroupingTree::moveObject(std::uint32_t object, const Box& box, const glm::vec3& velocity) {
    ARCOMP_CHECK(object < objectCount_, "an object of this tree");
    item_[object] = groupingItem(box, item_[object].color, velocity);
    hot_[object].bound = sphereAround(box);
    if (!moved_[object]) {
        moved_[object] = 1;
        movedObjects_.push_back(object);
    }
}

bool GroupingTree::refitNode(std::uint32_t g) {
    const GroupingItem fresh = mergedItem(item_[hot_[g].left], item_[hot_[g].right]);
    const float w = omega0(item_[hot_[g].left], item_[hot_[g].right], params_);
    const GroupingItem& old = item_[g];
    // Above a moved object, a group's box usually stays as it was and its
    // mean velocity and colour change by a member's share; once that moves
    // Ω0 by less than a hundredth of an Ωt step, the groups above would
    // not change their choice either, and the refit stops here.
    const float tolerance = 0.01f * params_.omegaStep;
    const bool same = fresh.box.min == old.box.min && fresh.box.max == old.box.max &&
                      params_.alphaF * glm::length(fresh.velocity - old.velocity) / params_.l0 < tolerance &&
                      params_.alphaC * glm::length(fresh.color - old.color) / params_.l0 < tolerance &&
                      std::abs(w - hot_[g].omega0) < tolerance;
    if (same) return false;
    item_[g] = fresh;
    hot_[g].bound = sphereAround(fresh.box);
    hot_[g].omega0 = w;
    return true;
}

void GroupingTree::refitUp(std::uint32_t g, std::vector<std::uint32_t>& tops, GroupingRebuildStats& stats) {
    for (; g != kNoGroupingNode; g = parent_[g]) {
        ++stats.refitted;
        if (!refitNode(g)) return;
        if (parent_[g] == kNoGroupingNode) tops.push_back(g);
    }
}

// Group g's pair no longer passes the last Ωt: g goes. Its child with the
// larger volume takes its place under g's parent; the other becomes
// top-level and groups again with what is near it.
void GroupingTree::cut(std::uint32_t g, std::vector<std::uint32_t>& freed, std::vector<std::uint32_t>& tops,
                       GroupingRebuildStats& stats) {
    const std::uint32_t a = hot_[g].left, b = hot_[g].right, p = parent_[g];
    ++stats.dissolved;
    if (p == kNoGroupingNode) {
        // A top-level group, or one set free by an earlier cut in this
        // rebuild (not yet back in the grid).
        if (rootSlot_[g] != kNoGroupingNode) dropRoot(g);
        parent_[a] = parent_[b] = kNoGroupingNode;
        freed.push_back(a);
        freed.push_back(b);
    } else {
        const bool keepA = item_[a].volume >= item_[b].volume;
        const std::uint32_t keep = keepA ? a : b, loose = keepA ? b : a;
        (hot_[p].left == g ? hot_[p].left : hot_[p].right) = keep;
        parent_[keep] = p;
        parent_[loose] = kNoGroupingNode;
        freed.push_back(loose);
    }
    alive_[g] = 0;
    hot_[g].left = hot_[g].right = parent_[g] = kNoGroupingNode;
    freeNodes_.push_back(g);
    if (p != kNoGroupingNode) refitUp(p, tops, stats);
}

GroupingRebuildStats GroupingTree::rebuildMoved() {
    GroupingRebuildStats stats;
    if (movedObjects_.empty()) return stats;
    std::vector<std::uint32_t> tops, freed;
    // Refit each moved object's chain of groups, leaf to top, until a group
    // no longer changes.
    for (std::uint32_t o : movedObjects_) {
        if (parent_[o] == kNoGroupingNode)
            tops.push_back(o);
        else
            refitUp(parent_[o], tops, stats);
    }
    // Walk each chain again and cut the groups that broke; a cut refits the
    // chain above it, so that chain is walked next.
    std::vector<std::uint32_t> check;
    for (std::uint32_t o : movedObjects_) check.push_back(parent_[o]);
    while (!check.empty()) {
        std::uint32_t g = check.back();
        check.pop_back();
        for (; g != kNoGroupingNode; g = parent_[g]) {
            if (!alive_[g] || double(hot_[g].omega0) < lastThreshold_) continue;
            const std::uint32_t p = parent_[g];
            cut(g, freed, tops, stats);
            check.push_back(p);
            break;
        }
    }
    // Top-level items that changed are placed in the grid again and offered
    // to their neighbours; then grouping goes on as at build time.
    std::vector<std::uint32_t> touched;
    for (std::uint32_t t : tops)
        if (alive_[t] && parent_[t] == kNoGroupingNode && rootSlot_[t] != kNoGroupingNode) {
            dropRoot(t);
            touched.push_back(t);
        }
    for (std::uint32_t c : freed)
        if (alive_[c] && parent_[c] == kNoGroupingNode && rootSlot_[c] == kNoGroupingNode) touched.push_back(c);
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    for (std::uint32_t t : touched) makeRoot(t);
    for (std::uint32_t t : touched) offerPairs(t, false);
    agglomerate(&stats);

    for (std::uint32_t o : movedObjects_) moved_[o] = 0;
    movedObjects_.clear();
    return stats;
}

}  // namespace arcomp
