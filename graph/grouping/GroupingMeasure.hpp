#pragma once
// The paper's grouping measure Ω between two objects or groups
// (perceptual-grouping, DESIGN.md §2). The tree is built from Ω0, the value
// at the reference distance L0; at run time Ω = Ω0·L0/Leye.
//
//   GroupingParams p;                          // the paper's constants
//   float w = omega0(a, b, p);                 // a, b: GroupingItem
//   bool asOne = omegaAt(w, eyeDistance, p) < p.omegaT;
//
// Units: lengths (box extents, distances, L0) in scene units, colour as
// linear RGB in 0..1, velocity in scene units per second. With the paper's
// constants two objects whose colours differ by more than 0.25 (RGB
// distance) never group at Ωt ≤ 0.1, and neither do two whose enclosing box
// is more than a third larger than their two boxes together.

#include "graph/core/Bounds.hpp"

namespace arcomp {

struct GroupingParams {
    float l0 = 5000.0f;      // reference eye distance, scene units
    float alphaP = 0.1f;     // proximity
    float alphaS = 2000.0f;  // shape similarity
    float alphaC = 2000.0f;  // colour similarity
    float alphaF = 0.1f;     // common motion
    // The build raises Ωt from start to max in steps (the paper: 0.001..0.1).
    float omegaStart = 0.001f;
    float omegaMax = 0.1f;
    float omegaStep = 0.001f;
    // The threshold the per-frame choice compares Ω with.
    float omegaT = 0.011f;

    int stepCount() const;
    // Ωt at build step k, computed the same way everywhere so that the
    // reference and the fast build compare against identical values.
    double thresholdAt(int step) const { return double(omegaStart) + double(step) * double(omegaStep); }
    double lastThreshold() const { return thresholdAt(stepCount() - 1); }
};

// One object or group as the measure sees it. A group's shape is the box
// enclosing its members, so its volume is that box's.
struct GroupingItem {
    Box box;
    float volume = 0.0f;
    glm::vec3 color{0.0f};     // linear RGB, 0..1
    glm::vec3 velocity{0.0f};  // scene units per second
};

// An object as the measure sees it: its box stands for its shape.
GroupingItem groupingItem(const Box& box, const glm::vec3& color, const glm::vec3& velocity = glm::vec3(0.0f));

// Ω0 of two items. Symmetric: omega0(a, b) == omega0(b, a) bit for bit.
float omega0(const GroupingItem& a, const GroupingItem& b, const GroupingParams& p);
// Ω at eye distance leye from Ω0.
float omegaAt(float omega0, float leye, const GroupingParams& p);
// The group of a and b: the box enclosing both, colour and velocity
// averaged by volume.
GroupingItem mergedItem(const GroupingItem& a, const GroupingItem& b);

}  // namespace arcomp
