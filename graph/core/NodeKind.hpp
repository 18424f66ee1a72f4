#pragma once
// What a scene node is, and how nodes are named: a NodeId indexes the
// scene's flat arrays (graph/core/Scene.hpp). Kinds defined elsewhere in
// graph/ keep their data in side tables that the node's payload indexes.

#include <cstdint>

namespace arcomp {

using NodeId = std::uint32_t;
inline constexpr NodeId kNoNode = ~NodeId{0};

enum class NodeKind : std::uint8_t { Group, Transform, Mesh, Lod, Grouping, SilhouetteRegion, PointCloud };

}  // namespace arcomp
