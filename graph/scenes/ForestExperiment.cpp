#include "graph/scenes/ForestExperiment.hpp"

#include "graph/core/SelectPass.hpp"

namespace arcomp {

ForestExperiment::ForestExperiment(ForestColouring colouring, const GroupingParams& params, glm::ivec2 viewport)
    : view(paperForestView(viewport)) {
    forest = addPaperForest(scene, scene.root(), grouping, lods, colouring);
    scene.update();
    buildGrouping(scene, forest.grouping, grouping, params);
}

const DrawList& ForestExperiment::select(ForestMode mode, float omegaT, GroupingProxy proxy) {
    GroupingNode& g = grouping.nodes[scene.payload(forest.grouping)];
    g.omegaT = omegaT;
    g.proxy = proxy;
    SelectSettings s;
    s.lod = mode == ForestMode::Full ? nullptr : &lods;
    s.grouping = mode == ForestMode::Grouped ? &grouping : nullptr;
    arcomp::select(scene, view, s, list_);
    return list_;
}

std::size_t ForestExperiment::triangles(ForestMode mode, float omegaT) {
    return drawnTriangles(scene, select(mode, omegaT));
}

std::size_t drawnTriangles(const Scene& scene, const DrawList& list) {
    std::size_t n = 0;
    for (const DrawItem& item : list.items)
        n += item.indexCount ? item.indexCount / 3 : scene.geometry(item.part.geometry).triangleCount();
    return n;
}

} // namespace arcomp
