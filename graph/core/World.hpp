#pragma once
// A scene and the side tables its special nodes index into, owned as one.
// A LOD node's payload is its entry in `lods`, a grouping node's in
// `grouping`, and so on; building through the tables' own add functions
// keeps every node's entry there, so select() treats a missing one as a
// broken invariant, not as "draw it some other way".
//
//   World world;
//   const MeshPart fine{world.scene.addGeometry(makeUvSphere(1.0f, 32, 16)), world.scene.addMaterial({})};
//   const MeshPart coarse{world.scene.addGeometry(makeUvSphere(1.0f, 8, 4)), fine.material};
//   const NodeId lod = world.scene.addNode(world.scene.root(), NodeKind::Lod, world.lods.add(settings));
//   world.scene.addMesh(lod, fine);
//   world.scene.addMesh(lod, coarse);
//   world.scene.update();
//   DrawList list;
//   select(world, view, {.shading = Shading::Phong, .timeSeconds = t}, list);

#include "graph/core/ObjectMotion.hpp"
#include "graph/core/Scene.hpp"
#include "graph/grouping/GroupingNodes.hpp"
#include "graph/lod/Lod.hpp"
#include "graph/points/PointCloudNodes.hpp"
#include "graph/silhouette/HoldoutMeshes.hpp"
#include "graph/silhouette/SilhouetteNodes.hpp"

#include <vector>

namespace arcomp {

struct World {
    Scene scene;
    LodTable lods;                       // NodeKind::Lod
    GroupingNodes grouping;              // NodeKind::Grouping
    SilhouetteNodes silhouettes;         // NodeKind::SilhouetteRegion
    PointCloudNodes pointClouds;         // NodeKind::PointCloud
    HoldoutMeshes holdouts;              // per mesh node that cuts people out of the video
    std::vector<ObjectMotion> motions;   // the config's movers
};

// Puts every mover where it is at `timeSeconds`, updates the scene and
// rebuilds only the grouping branches that hold a mover.
void moveObjects(World& world, double timeSeconds);

} // namespace arcomp
