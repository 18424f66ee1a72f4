#pragma once
// The scene of the grouping paper's experiment (perceptual-grouping,
// DESIGN.md §2): 32 procedurally made trees of 105 triangles (a trunk and a
// crown) with a 12-triangle simplified level, standing in a 4 × 8 block
// whose boxes tile without gaps, as the paper's Fig. 9 and 11 show a
// dense stand. Units are centimetres, so the paper's L0 = 5000 is 50 m.
//
//   Scene scene; GroupingNodes grouping; LodTable lods;
//   PaperForest f = addPaperForest(scene, scene.root(), grouping, lods, ForestColouring::Mixed);
//   scene.update();
//   buildGrouping(scene, f.grouping, grouping, GroupingParams{});
//   View v = paperForestView({1280, 720});
//
// Mixed: 5 of the trees have red crowns; Green: all crowns green.

#include "graph/core/View.hpp"
#include "graph/grouping/GroupingNodes.hpp"
#include "graph/lod/Lod.hpp"

namespace arcomp {

enum class ForestColouring : std::uint8_t { Mixed, Green };

struct PaperForest {
    NodeId grouping = kNoNode;
    std::vector<NodeId> trees;  // the grouping node's children, object i = trees[i]
    std::vector<bool> red;      // per tree
};

inline constexpr std::size_t kForestTrees = 32;
inline constexpr std::size_t kTreeTriangles = 105;
inline constexpr std::size_t kSimplifiedTreeTriangles = 12;
// Trees nearer than this (cm) show their full level, the rest the simplified one.
inline constexpr float kForestLodDistance = 4400.0f;

Geometry makeTreeCrown(bool simplified);
Geometry makeTreeTrunk(bool simplified);

PaperForest addPaperForest(Scene& scene, NodeId parent, GroupingNodes& grouping, LodTable& lods,
                           ForestColouring colouring);
// The same trees under an existing grouping node (after whatever else it holds).
PaperForest addPaperForestTo(Scene& scene, NodeId groupingNode, LodTable& lods, ForestColouring colouring);
// The fixed viewpoint of the experiment: in front of the block, at eye
// height, about L0 away.
View paperForestView(glm::ivec2 viewport);

}  // namespace arcomp
