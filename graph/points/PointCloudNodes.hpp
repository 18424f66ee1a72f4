#pragma once
// The side table behind the scene's PointCloud nodes: each node's payload
// indexes one LdiSet here, whose points are in the node's local space.
//
//   PointCloudNodes clouds;
//   NodeId tree = clouds.add(scene, scene.root(), buildLdis(cloud, cameras), "tree");
//   const LdiSet& ldis = clouds.at(scene, tree);   // what the renderer draws
//
// The renderer draws such a node with an LdiRenderer whose eye is the
// camera's eye taken into the node's local space, and shows the image as
// a layer. Keep the table alive as long as the scene: nodes refer to it by
// index, and LdiSets never move once added (they are held by pointer).

#include "graph/core/Scene.hpp"
#include "graph/points/Ldi.hpp"

#include <memory>
#include <string>
#include <vector>

namespace arcomp {

class PointCloudNodes {
public:
    // Adds a PointCloud node under `parent` whose local bound encloses the points.
    NodeId add(Scene& scene, NodeId parent, LdiSet set, std::string name = {});
    // The LdiSet of a PointCloud node; throws std::out_of_range for any other node.
    const LdiSet& at(const Scene& scene, NodeId node) const;
    std::size_t size() const { return sets_.size(); }

private:
    std::vector<std::unique_ptr<LdiSet>> sets_;
};

}  // namespace arcomp
