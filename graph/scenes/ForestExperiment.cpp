#include "graph/scenes/ForestExperiment.hpp"

#include "graph/core/SelectPass.hpp"

namespace arcomp {

ForestExperiment::ForestExperiment(ForestColouring colouring, const GroupingParams& params, glm::ivec2 viewport)
    : view(paperForestView(viewport)) {
    Scene& scene = world.scene;
    forest = addPaperForest(scene, scene.root(), world.grouping, world.lods, colouring);
    scene.update();
    buildGrouping(scene, forest.grouping, world.grouping, params);
}

const DrawList& ForestExperiment::select(ForestMode mode, float omegaT, GroupingProxy proxy) {
    GroupingNode& g = world.grouping.nodes[world.scene.payload(forest.grouping)];
    g.omegaT = omegaT;
    g.proxy = proxy;
    arcomp::select(world, view, {.lod = mode != ForestMode::Full, .grouping = mode == ForestMode::Grouped}, list_);
    return list_;
}

std::size_t ForestExperiment::triangles(ForestMode mode, float omegaT) {
    return drawnTriangles(world.scene, select(mode, omegaT));
}

std::size_t drawnTriangles(const Scene& scene, const DrawList& list) {
    std::size_t n = 0;
    for (const DrawItem& item : list.items)
        n += item.indexCount ? item.indexCount / 3 : scene.geometry(item.part.geometry).triangleCount();
    return n;
}

}  // namespace arcomp
