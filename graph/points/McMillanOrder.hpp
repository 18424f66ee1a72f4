#pragma once
// McMillan's occlusion-compatible order for an LDI: the order in which to
// draw its points so that, seen from a new eye, farther points come before
// the nearer ones that may cover them, without sorting by depth.
//
//   std::vector<std::uint32_t> ids;
//   appendBackToFront(ldi, view.eye, ids);   // point ids, back to front
//
// The epipole p is where the line from the LDI's eye e0 to the new eye e1
// meets the LDI's screen plane. Its column and row split the screen into up
// to four sheets. When e1 is in front of e0 every sheet is scanned towards
// p, when behind away from p; p can lie left of, on or right of the screen
// and above, on or below it: 9 x 2 cases, all handled by the same loops.
//
// Within a pixel the points lie along one ray from e0; the one nearest to e1
// sits where the ray passes closest to e1. The pixel's depth-sorted list is
// walked from both ends towards that place, which is the plain one-way walk
// of the paper whenever all of the pixel's points lie on one side of it (e1
// outside the model), and stays correct when e1 is among the points.

#include "graph/points/Ldi.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace arcomp {

enum class EpipoleSide : std::uint8_t { Before, Inside, After };  // per axis: < 0, on screen, >= size

struct Epipole {
    glm::vec2 pixel{0.0f};  // screen position; very large when e1 is (nearly) on e0's screen plane
    bool inFront = false;   // e1 in front of e0 (positive depth in e0's camera)
    EpipoleSide column = EpipoleSide::Inside;
    EpipoleSide row = EpipoleSide::Inside;
};

Epipole epipoleOf(const LdiCamera& camera, const glm::vec3& eye);

// Appends the LDI's point ids in back-to-front order as seen from `eye`.
void appendBackToFront(const Ldi& ldi, const glm::vec3& eye, std::vector<std::uint32_t>& out);
// The same order as LDI slots (positions in ldi.points) plus `base`, into
// `slots` (ldi.points.size() of them): a renderer that keeps its per-point
// data in slot order reads it almost sequentially along this walk. The
// walk is cut into `parts` pieces of about equal size, so that several
// threads can share it: piece `part` fills its share of `slots`, and all
// pieces together give the whole order.
void writeSlotsBackToFront(const Ldi& ldi, const glm::vec3& eye, std::uint32_t base, std::span<std::uint32_t> slots,
                           std::size_t part = 0, std::size_t parts = 1);

}  // namespace arcomp
