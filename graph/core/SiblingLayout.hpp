#pragma once
// The scene's nodes as the select pass reads them: in slots where every
// node's children sit side by side, and no node is reached through a
// NodeId. Scene::update() keeps it: the structure when nodes were added,
// the bounds of what changed.
//
//   const SiblingLayout& l = scene.siblingLayout();
//   for (std::uint32_t c = l.slots[0].firstChild; c < l.childEnd(0); ++c) use(l.slots[c].node, l.bound(c));
//
// Each bound is kept twice, for the two ways the walk reads it:
// - culling a node's children streams one run of four float arrays (centre
//   x, y, z and radius) that SIMD tests several spheres at a time
//   (Frustum::classifyRun);
// - going into one node reads its Slot: everything about it in half a cache
//   line, not one line from each of nine arrays. Most of a frame's memory
//   traffic is there, one visible object at a time.
//
// A node's children take their slots when the depth-first walk reaches the
// node, so an object's own subtree (LOD node, levels) lies close together
// after the run of its siblings. A transform or group with one child and no
// bound of its own has no slot: the child takes its place (Scene.cpp), and
// slotOf gives every node of such a chain the one slot.

#include "graph/core/Bounds.hpp"
#include "graph/core/NodeKind.hpp"

#include <cstdint>
#include <vector>

namespace arcomp {

struct SiblingLayout {
    struct Slot {
        Sphere bound;  // world
        NodeId node;
        std::uint32_t payload;
        std::uint32_t firstChild;  // the children are slots [firstChild, firstChild + childCount)
        std::uint32_t childCount : 24;
        NodeKind kind : 8;
    };
    static constexpr std::uint32_t kMaxChildren = (1u << 24) - 1u;

    // Per slot; slot 0 is the root.
    std::vector<Slot> slots;
    std::vector<float> centerX, centerY, centerZ, radius;  // the bounds again, for runs
    // Per NodeId: its slot.
    std::vector<std::uint32_t> slotOf;

    std::size_t size() const { return slots.size(); }
    const Sphere& bound(std::uint32_t slot) const { return slots[slot].bound; }
    std::uint32_t childEnd(std::uint32_t slot) const { return slots[slot].firstChild + slots[slot].childCount; }
    void setBound(std::uint32_t slot, const Sphere& s) {
        slots[slot].bound = s;
        centerX[slot] = s.center.x;
        centerY[slot] = s.center.y;
        centerZ[slot] = s.center.z;
        radius[slot] = s.radius;
    }
};

static_assert(sizeof(SiblingLayout::Slot) == 32, "two slots to a cache line");

}  // namespace arcomp
