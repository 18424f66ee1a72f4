#pragma once
// The station config's `grouping` section (configs/README.md): the
// grouping paper's parameters, the proxy kind, and what is grouped. Absent,
// nothing is grouped and the scene is drawn as before.
//
//   readGroupingConfig(root, cfg.grouping);   // from loadStationConfig

#include "graph/grouping/GroupingNodes.hpp"
#include "graph/scenes/PaperForest.hpp"

#include <optional>

namespace arcomp {

class YamlMap;

struct GroupingConfig {
    bool enabled = false;
    GroupingParams params;
    GroupingProxy proxy = GroupingProxy::Box;
    float proxyAlpha = 0.7f;
    float impostorPixelsPerUnit = 0.5f;
    // Puts the config's scene objects under the grouping node.
    bool objects = false;
    // Adds the paper's 32-tree forest under the grouping node.
    std::optional<ForestColouring> forest;
};

void readGroupingConfig(YamlMap& root, GroupingConfig& out);

}  // namespace arcomp
