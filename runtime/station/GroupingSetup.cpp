#include "runtime/station/GroupingSetup.hpp"

namespace arcomp {

NodeId beginGrouping(const GroupingConfig& cfg, Scene& scene, GroupingNodes& table) {
    if (!cfg.enabled) return kNoNode;
    return addGroupingNode(scene, scene.root(), table, "grouping");
}

void finishGrouping(const GroupingConfig& cfg, Scene& scene, NodeId groupingNode, GroupingNodes& table,
                    LodTable& lods) {
    if (groupingNode == kNoNode) return;
    if (cfg.forest) addPaperForestTo(scene, groupingNode, lods, *cfg.forest);
    scene.update();
    buildGrouping(scene, groupingNode, table, cfg.params);
    GroupingNode& g = table.nodes[scene.payload(groupingNode)];
    g.proxy = cfg.proxy;
    g.proxyAlpha = cfg.proxyAlpha;
    g.impostorPixelsPerUnit = cfg.impostorPixelsPerUnit;
}

}  // namespace arcomp
