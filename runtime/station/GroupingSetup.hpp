#pragma once
// Turns a config's `grouping` section into scene content: a grouping node
// under the root (holding the config's objects when `objects: true`, and
// the paper's forest when asked), and its tree, built once everything is
// in place. Used by buildScene in two calls around the objects.
//
//   NodeId g = beginGrouping(cfg.grouping, scene, table);   // kNoNode when off
//   ... objects, under g when cfg.grouping.objects ...
//   finishGrouping(cfg.grouping, scene, g, table, lods);

#include "graph/lod/Lod.hpp"
#include "runtime/config/GroupingConfig.hpp"

namespace arcomp {

NodeId beginGrouping(const GroupingConfig& cfg, Scene& scene, GroupingNodes& table);
void finishGrouping(const GroupingConfig& cfg, Scene& scene, NodeId groupingNode, GroupingNodes& table, LodTable& lods);

}  // namespace arcomp
