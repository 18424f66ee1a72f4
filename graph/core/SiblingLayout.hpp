#pragma once
// The scene's nodes as the select pass reads them: in slots where every
// node's children sit side by side, so that culling a node's children
// streams one run of four float arrays (centre x, y, z and radius) that
// SIMD tests several spheres at a time (Frustum::classifyRun), and no node
// is reached through a NodeId. Scene::update() keeps it: the structure when
// nodes were added, the bounds of what changed.
//
//   const SiblingLayout& l = scene.siblingLayout();
//   for (std::uint32_t c = l.firstChild[0]; c < l.childEnd[0]; ++c) use(l.node[c], l.bound(c));
//
// A node's children take their slots when the depth-first walk reaches the
// node, so an object's own subtree (transform, LOD node, levels) lies close
// together after the run of its siblings.

#include "graph/core/Bounds.hpp"
#include "graph/core/NodeKind.hpp"

#include <cstdint>
#include <vector>

namespace arcomp {

struct SiblingLayout {
    // Per slot; slot 0 is the root.
    std::vector<float> centerX, centerY, centerZ, radius;  // world bound
    std::vector<NodeKind> kind;
    std::vector<std::uint32_t> payload;
    std::vector<NodeId> node;
    // The slot's children are the slots [firstChild, childEnd).
    std::vector<std::uint32_t> firstChild, childEnd;
    // Per NodeId: its slot.
    std::vector<std::uint32_t> slotOf;

    std::size_t size() const { return node.size(); }
    Sphere bound(std::uint32_t slot) const { return {{centerX[slot], centerY[slot], centerZ[slot]}, radius[slot]}; }
    void setBound(std::uint32_t slot, const Sphere& s) {
        centerX[slot] = s.center.x;
        centerY[slot] = s.center.y;
        centerZ[slot] = s.center.z;
        radius[slot] = s.radius;
    }
};

} // namespace arcomp
