#pragma once
// Level-of-detail nodes. A NodeKind::Lod node's children are its levels,
// finest first; each may be a whole subtree. The select pass asks
// LodTable::choose() for the level in the same walk that culls, and visits
// only that child (and, during a cross-fade, the level fading out).
//
//   LodNode n;
//   n.policy = LodPolicy::Distance;
//   n.setThresholds({50.0f, 200.0f});           // [0,50) → 0, [50,200) → 1, beyond → 2
//   NodeId lod = world.scene.addNode(parent, NodeKind::Lod, world.lods.add(n));
//   world.scene.addMesh(lod, fine); world.scene.addMesh(lod, medium); world.scene.addMesh(lod, coarse);
//   select(world, view, {.gaze = gaze, .timeSeconds = t}, list);   // graph/core/World.hpp
//
// Policies, chosen per node: distance from the eye to the bound's centre (as
// OpenSceneGraph's DISTANCE_FROM_EYE_POINT), projected diameter in pixels (as
// PIXEL_SIZE_ON_SCREEN), the paper's gaze acuity k1·k2 (graph/lod/GazeAcuity.hpp),
// or pixels weighted by acuity. A band around each threshold (hysteresis)
// keeps a node hovering at a boundary from flipping level every frame; the
// per-node previous level lives in LodTable, not in the scene.

#include "graph/lod/GazeAcuity.hpp"

#include <array>
#include <cstdint>
#include <initializer_list>
#include <vector>

namespace arcomp {

inline constexpr std::size_t kMaxLodLevels = 8;
inline constexpr std::uint8_t kNoLevel = 0xff;

enum class LodPolicy : std::uint8_t {
    Distance,               // world units from the eye; thresholds ascending
    ScreenSize,             // projected diameter in pixels; thresholds descending
    GazeAcuity,             // k1·k2 in [0, 1]; thresholds descending
    ScreenSizeTimesAcuity,  // pixels · k1·k2; thresholds descending
};

// What a node's level is chosen by: the part of its settings that the
// select pass reads for every visible LOD node.
struct LodRule {
    LodPolicy policy = LodPolicy::Distance;
    std::uint8_t levelCount = 1;
    // thresholds[i] is the boundary between level i and i + 1. Distance: the
    // far end of level i. The others: the least value level i needs.
    std::array<float, kMaxLodLevels - 1> thresholds{};
    // Relative half-width of the band around each threshold: to leave its
    // level, a node must pass the boundary by this fraction of it.
    float hysteresis = 0.1f;
    float fadeSeconds = 0.0f;  // cross-fade time; 0 switches at once

    // Sets levelCount to thresholds.size() + 1; aborts beyond kMaxLodLevels.
    void setThresholds(std::initializer_list<float> t);

    bool operator==(const LodRule&) const = default;
};

// An LOD node's settings: its rule, and the shape the gaze policies see.
struct LodNode : LodRule {
    // The object as a sphere of its mean radius, in the LOD node's frame;
    // only the gaze policies use it (representative point, DESIGN.md §1).
    glm::vec3 center{0.0f};
    float meanRadius = 1.0f;
    GazeAcuityParams acuity{};
};

// What a policy reads about a node this frame.
struct LodInputs {
    float distance = 0.0f;  // eye to bound centre
    float pixels = 0.0f;    // projected diameter of the bound
    float acuity = 1.0f;    // k1·k2
};

// The value a node's policy compares against its thresholds.
inline float lodMetric(LodPolicy policy, const LodInputs& in) {
    switch (policy) {
    case LodPolicy::Distance: return in.distance;
    case LodPolicy::ScreenSize: return in.pixels;
    case LodPolicy::GazeAcuity: return in.acuity;
    case LodPolicy::ScreenSizeTimesAcuity: return in.pixels * in.acuity;
    }
    return 0.0f;
}

// The level for `metric`, given the level shown last frame (kNoLevel: none).
// Boundaries next to the previous level are pushed away from it by the band.
// Inline, as choose(): the select pass calls it once per visible LOD node.
inline std::uint8_t chooseLevel(const LodRule& node, float metric, std::uint8_t previous) {
    const bool up = node.policy == LodPolicy::Distance;  // thresholds ascending
    std::uint8_t level = 0;
    for (std::uint8_t i = 0; i + 1 < node.levelCount; ++i) {
        float t = node.thresholds[i];
        if (previous != kNoLevel) {
            // Boundary i separates levels ≤ i (finer) from > i (coarser).
            // Shown on the fine side: coarsening needs the band crossed too.
            const bool wasFine = previous <= i;
            const float band = node.hysteresis * t;
            t += (wasFine == up) ? band : -band;
        }
        const bool coarser = up ? metric >= t : metric < t;
        if (!coarser) break;
        level = static_cast<std::uint8_t>(i + 1);
    }
    return level;
}

struct LodChoice {
    std::uint8_t level = 0;
    std::uint8_t fadingLevel = kNoLevel;  // level fading out, or kNoLevel
    float fade = 1.0f;                    // weight of `level`; fadingLevel gets 1 - fade
};

class LodTable {
public:
    std::uint32_t add(const LodNode& node);
    std::size_t size() const { return history_.size(); }
    const LodRule& rule(std::uint32_t i) const { return rules_[history_[i].rule]; }
    LodNode node(std::uint32_t i) const;

    // Level shown last (kNoLevel before the first choice).
    std::uint8_t previousLevel(std::uint32_t i) const { return history_[i].level; }
    // Forgets every node's history, e.g. after a cut in a replay.
    void reset();

    // Picks node i's level for this frame and records it.
    LodChoice choose(std::uint32_t i, const LodInputs& in, double timeSeconds) {
        History& h = history_[i];
        const LodRule& rule = rules_[h.rule];
        const bool fresh = timeSeconds - h.lastChosen > kStaleSeconds;
        const std::uint8_t previous = fresh ? kNoLevel : h.level;
        const std::uint8_t level = chooseLevel(rule, lodMetric(rule.policy, in), previous);
        h.lastChosen = timeSeconds;
        h.level = level;
        if (rule.fadeSeconds <= 0.0f) return {level, kNoLevel, 1.0f};
        return fade(i, previous, level, fresh, timeSeconds);
    }

    // Inputs for the gaze policies: the acuity of node i whose LOD node has
    // world matrix `world`, seen from `eye` with `gaze` (unit, world), and
    // the representative point kept for next frame.
    float acuity(std::uint32_t i, const glm::mat4& world, const glm::vec3& eye, const glm::vec3& gaze,
                 double timeSeconds);

private:
    // A node unseen for longer than this starts afresh: no band around its
    // old level, no fade from it, no angular speed over the gap.
    static constexpr double kStaleSeconds = 0.25;

    // What choose() reads and writes of a node, a quarter of a cache line.
    // The rule it names is most often shared: a scene's LOD nodes have few
    // distinct rules, which stay in cache, so a visible node costs the walk
    // 16 bytes here rather than its own line, read and written back.
    struct History {
        double lastChosen;
        std::uint32_t rule;                // index into rules_
        std::uint8_t level = kNoLevel;     // shown last
        std::uint8_t fadeFrom = kNoLevel;  // level fading out
    };
    static_assert(sizeof(History) == 16, "four nodes' history to a cache line");
    // The gaze policies' side of a node, read only by acuity().
    struct GazeShape {
        glm::vec3 center;
        float meanRadius;
        GazeAcuityParams acuity;
        TrackedPoint tracked;
        double trackedAt = 0.0;
    };

    // choose() for node i, whose rule has a cross-fade time.
    LodChoice fade(std::uint32_t i, std::uint8_t previous, std::uint8_t level, bool fresh, double timeSeconds);

    std::vector<LodRule> rules_;  // a rule repeated by nodes added close together is kept once
    std::vector<History> history_;
    std::vector<double> fadeStart_;  // per node, read by fade() only
    std::vector<GazeShape> gaze_;
};

}  // namespace arcomp
