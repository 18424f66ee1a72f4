#pragma once
// The grouping paper's Fig. 10 as a computation: the triangles drawn from
// the fixed viewpoint at a given Ωt, with full detail, with simplification
// only (each tree's LOD), or with grouping and simplification.
//
//   ForestExperiment mixed(ForestColouring::Mixed);
//   std::size_t n = mixed.triangles(ForestMode::Grouped, 0.011f);

#include "graph/core/DrawList.hpp"
#include "graph/core/World.hpp"
#include "graph/scenes/PaperForest.hpp"

namespace arcomp {

enum class ForestMode : std::uint8_t { Full, Simplified, Grouped };

class ForestExperiment {
public:
    explicit ForestExperiment(ForestColouring colouring, const GroupingParams& params = {},
                              glm::ivec2 viewport = {1280, 720});

    // Selects with the given Ωt; the list stays valid until the next call.
    const DrawList& select(ForestMode mode, float omegaT, GroupingProxy proxy = GroupingProxy::Box);
    std::size_t triangles(ForestMode mode, float omegaT);

    World world;
    PaperForest forest;
    View view;

private:
    DrawList list_;
};

std::size_t drawnTriangles(const Scene& scene, const DrawList& list);

}  // namespace arcomp
