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

#include "graph/animation/AnimationPlayer.hpp"
#include "graph/core/ObjectMotion.hpp"
#include "graph/core/ObjectOpacity.hpp"
#include "graph/core/Scene.hpp"
#include "graph/grouping/GroupingNodes.hpp"
#include "graph/lod/Lod.hpp"
#include "graph/points/PointCloudNodes.hpp"
#include "graph/silhouette/HoldoutMeshes.hpp"
#include "graph/silhouette/SilhouetteNodes.hpp"

#include <string>
#include <utility>
#include <vector>

namespace arcomp {

// A config object's model animation: the player, and the object's placing
// transform, whose subtree the animation changes.
struct ObjectAnimation {
    AnimationPlayer player;
    NodeId node = kNoNode;
    // As for a mover: the grouping node that holds the object, and its index
    // among that node's objects, so only its branch is rebuilt.
    NodeId groupingNode = kNoNode;
    std::uint32_t groupingObject = 0;
};

// A config object by its name: the transform that places it, and its
// model's animations, any of which a trigger or a cue may play.
struct NamedObject {
    std::string name;
    NodeId node = kNoNode;
    std::vector<ModelAnimation> animations{};
};

struct World {
    Scene scene;
    LodTable lods;                            // NodeKind::Lod
    GroupingNodes grouping;                   // NodeKind::Grouping
    SilhouetteNodes silhouettes;              // NodeKind::SilhouetteRegion
    PointCloudNodes pointClouds;              // NodeKind::PointCloud
    HoldoutMeshes holdouts;                   // per mesh node that cuts people out of the video
    std::vector<ObjectMotion> motions;        // the config's movers
    std::vector<ObjectAnimation> animations;  // the config's animated models
    std::vector<ObjectOpacity> opacity;       // objects hidden or fading, applied by select()
    std::vector<NamedObject> objects;         // the config's objects, in its order
};

// The grouping node that holds `node` as one of its objects, and the
// object's index there, so that a change to it rebuilds only its branch;
// {kNoNode, 0} when its parent is no grouping node.
std::pair<NodeId, std::uint32_t> groupingSlot(const World& world, NodeId node);
// The object by name; null when there is none.
const NamedObject* findObject(const World& world, const std::string& name);

// Puts every mover where it is at `timeSeconds`, updates the scene and
// rebuilds only the grouping branches that hold a mover.
void moveObjects(World& world, double timeSeconds);
// Poses every animated object for `timeSeconds` (the video frame's time),
// updates the scene and rebuilds the grouping branches that hold one.
void animateObjects(World& world, double timeSeconds);
// Whether node n or one of its ancestors is a mover or an animated object:
// its shape on screen changes from frame to frame.
bool movesOverTime(const World& world, NodeId n);

}  // namespace arcomp
