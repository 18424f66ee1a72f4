#pragma once
// The paper's grouping tree (perceptual-grouping, DESIGN.md §2): leaves are
// objects, each inner node the group of its two children. Built once at
// load time by the paper's procedure (raise Ωt step by step; merge the pair
// of smallest Ω0 while it is below Ωt), which amounts to always merging the
// globally smallest pair until it reaches the last Ωt. Here that runs on a
// priority queue of candidate pairs, with a grid over the top-level items
// that only offers partners close enough to pass the last Ωt.
//
//   GroupingTree tree;
//   tree.build(items, params);                 // items: one GroupingItem per object
//   for (auto r : tree.roots()) ...            // top-level groups and lone objects
//   tree.moveObject(i, newBox, velocity);      // later, when objects move
//   tree.rebuildMoved();                       // refits, re-groups only what broke
//
// Data is flat: node i's item, children, parent and merge Ω0 sit in arrays.
// Leaves are nodes 0..n-1 (node i is object i); groups follow in the order
// they were made.

#include "graph/grouping/GroupingMeasure.hpp"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

namespace arcomp {

inline constexpr std::uint32_t kNoGroupingNode = ~std::uint32_t{0};

struct GroupingRebuildStats {
    std::size_t refitted = 0;   // groups whose box and Ω0 were recomputed
    std::size_t dissolved = 0;  // groups cut: their pair no longer passed the last Ωt
    std::size_t merged = 0;     // groups made anew
};

class GroupingTree {
public:
    void build(std::span<const GroupingItem> objects, const GroupingParams& params);

    const GroupingParams& params() const { return params_; }
    std::size_t objectCount() const { return objectCount_; }
    std::size_t nodeCount() const { return item_.size(); }
    bool isLeaf(std::uint32_t n) const { return hot_[n].left == kNoGroupingNode; }
    bool alive(std::uint32_t n) const { return alive_[n] != 0; }
    const GroupingItem& item(std::uint32_t n) const { return item_[n]; }
    // The sphere around node n's box, for culling.
    const Sphere& bound(std::uint32_t n) const { return hot_[n].bound; }
    std::uint32_t left(std::uint32_t n) const { return hot_[n].left; }
    std::uint32_t right(std::uint32_t n) const { return hot_[n].right; }
    std::uint32_t parent(std::uint32_t n) const { return parent_[n]; }
    // Ω0 of the pair this group was made from (now, after any refit).
    float mergeOmega0(std::uint32_t n) const { return hot_[n].omega0; }
    // Top-level nodes: groups with no parent and objects in no group.
    std::span<const std::uint32_t> roots() const { return roots_; }
    // Longest root-to-leaf path in nodes (a lone object counts 1).
    std::size_t depth() const;
    // Objects under node n.
    std::vector<std::uint32_t> objectsUnder(std::uint32_t n) const;

    // Records an object's new box and velocity; the tree changes at
    // rebuildMoved().
    void moveObject(std::uint32_t object, const Box& box, const glm::vec3& velocity);
    // Refits the groups above moved objects (up to where nothing changes
    // any more); cuts each group whose pair no longer passes the last Ωt,
    // its larger child taking its place and the other set free; then lets
    // the freed and changed top-level items group again with what is near
    // them. Branches no moved object belongs to stay as they are.
    GroupingRebuildStats rebuildMoved();

private:
    struct Candidate {
        float omega;
        std::uint32_t a, b;  // a < b
        bool operator>(const Candidate& o) const {
            if (omega != o.omega) return omega > o.omega;
            if (a != o.a) return a > o.a;
            return b > o.b;
        }
    };

    std::uint32_t addNode(const GroupingItem& item);
    void makeRoot(std::uint32_t n);
    void dropRoot(std::uint32_t n);
    // How far (in x and z) a partner's centre may lie from n's, added to
    // the partner's own reach, for the pair to possibly pass the last Ωt.
    glm::vec2 reach(std::uint32_t n) const;
    int levelFor(std::uint32_t n) const;
    std::int64_t cellIndex(int level, float x) const;
    static std::uint64_t cellKey(int level, std::int64_t ix, std::int64_t iz);
    void gridInsert(std::uint32_t n);
    void gridErase(std::uint32_t n);
    // Pushes every pair of n with another root whose Ω0 is below the last Ωt.
    void offerPairs(std::uint32_t n, bool onlyLater);
    void consider(std::uint32_t n, std::uint32_t other, bool onlyLater);
    void agglomerate(GroupingRebuildStats* stats);
    bool refitNode(std::uint32_t g);  // false when g did not change enough to matter
    void refitUp(std::uint32_t g, std::vector<std::uint32_t>& tops, GroupingRebuildStats& stats);
    void cut(std::uint32_t g, std::vector<std::uint32_t>& freed, std::vector<std::uint32_t>& tops,
             GroupingRebuildStats& stats);
    void pushCandidate(std::uint32_t a, std::uint32_t b, float omega);

    GroupingParams params_;
    double lastThreshold_ = 0.0;
    std::size_t objectCount_ = 0;

    // What the select pass reads of a node, together in one cache line.
    struct Hot {
        Sphere bound;
        float omega0;
        std::uint32_t left, right;
    };
    std::vector<Hot> hot_;
    std::vector<GroupingItem> item_;
    std::vector<std::uint32_t> parent_;
    std::vector<std::uint8_t> alive_;
    std::vector<std::uint32_t> roots_;
    std::vector<std::uint32_t> rootSlot_;   // position in roots_, or kNoGroupingNode
    std::vector<std::uint64_t> cell_;       // grid cell of a root
    std::vector<glm::vec2> reach_;          // of a root, as reach() gave when it was placed
    std::vector<std::uint32_t> unbounded_;  // roots with no finite reach: paired with everything
    std::vector<std::uint32_t> freeNodes_;  // dissolved groups' slots, reused

    std::vector<Candidate> heap_;
    // A hierarchical grid over the roots' centres in x and z: level L has
    // cells of cellSize_·2^L and holds the roots whose reach fits half a cell.
    static constexpr int kLevels = 32;
    float cellSize_ = 1.0f;
    float proximityReach_ = 0.0f;  // the L2 bound, from the proximity term
    float shapeFactor_ = 0.0f;     // reach per unit of extent, from the shape term; 0: none
    std::array<std::vector<std::uint32_t>, kLevels> levelItems_{};  // the roots at each level
    std::array<double, kLevels> levelCell_{};
    std::vector<std::uint32_t> levelSlot_;  // a root's position in its level's list
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid_;

    std::vector<std::uint32_t> movedObjects_;
    std::vector<std::uint8_t> moved_;
};

}  // namespace arcomp
