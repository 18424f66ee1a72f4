#pragma once
// The cost table corrected by whole frames of a scene (paper: uniform-frame-
// time, t = A·pixels + B). A table measured one object at a time
// (tools/bench/probes/CostCalibration.hpp) misses what a scene adds: objects hiding one
// another, overdraw, the mix of meshes drawn together. Timed frames of the
// scene scale it: every shading's A by a gain of its own, and every B by
// one gain, fitted to all the frames at once.
//
//   CostTableFit fit(singleObjectTable);
//   fit.addFrame(items, measuredMs - singleObjectTable.overheadMs);   // per timed frame
//   CostModel table = fit.table();
//
// Why scale the single-object table rather than fit numbers of its own: its
// shape is the machine's. On llvmpipe a pixel's cost depends on the level as
// well as the shading (one mountain of bench budget: 2-2.6 times as much per
// pixel at its 10k-triangle level 0 as at its 128-triangle level 2), and an
// item's fixed cost on the shading as well as the level (level 0: 2.4 ms
// Phong, 1.1 ms unlit). One object measured alone gets that shape right; a
// hundred noisy frames of the scene do not. Fitted with A per shading and B
// per level, the table put level 2's B at zero, and the controller's frames
// (near objects fine and lit, far ones coarse and unlit) took 1.5-2.2 times
// their prediction until the online gain caught up. Fitted pair by pair (24
// numbers from 150 frames), level 0's unlit A and Phong B came out at a
// sixth to a third of what one object measured, and in one run of three
// the controller lowered a near object and raised it again every fifth frame
// (46 frames swinging between -50% and +57% of the target). What the scene
// changes depends on the shading: a hidden pixel skips its shading but not
// its rasterization, so the dearer the shading, the more a scene's hidden
// pixels save against one object alone; hence a gain per shading.

#include "graph/budget/CostModel.hpp"
#include "graph/budget/RecursiveLeastSquares.hpp"

#include <span>
#include <vector>

namespace arcomp {

// One drawn item as the table charges it.
struct ChargedItem {
    std::size_t level = 0;
    Shading shading = Shading::Phong;
    double pixels = 0.0;  // graph/budget/OnScreenPixels.hpp
};

class CostTableFit {
public:
    explicit CostTableFit(const CostModel& singleObject);

    // A timed frame: what it drew, and its measured time less the frame
    // overhead. Levels beyond the table's are charged as its last. A frame
    // whose time or pixels are not finite is left out.
    void addFrame(std::span<const ChargedItem> items, double itemsMs);
    std::size_t frames() const { return fit_.samples(); }

    // The gains so far: A's of each shading, then every B's.
    std::span<const double> gains() const { return fit_.parameters(); }
    // The single-object table scaled by the gains (none below zero).
    CostModel table() const;

private:
    CostModel singleObject_;
    RecursiveLeastSquares fit_;
    std::vector<double> x_;
};

}  // namespace arcomp
