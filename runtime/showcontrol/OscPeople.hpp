#pragma once
// A frame's people in arcomp's OSC address space, one bundle a frame, the
// messages in this order:
//   /arcomp/frame  i frame  f seconds  s units  i people
//   /arcomp/enter  i id  f x  f y                       each id new this frame
//   /arcomp/person i id  f x  f y  f vx  f vy  f height_m  f age_s  i seen
//                  i box_x  i box_y  i box_w  i box_h    each person, by id
//   /arcomp/leave  i id                                  each id gone this frame
// units is "floor_m" (x, z on the floor in metres; velocities in metres a
// second) or "image" (the picture's 0..1, u right, v down). seconds is
// video time, so a replay stamps its messages as the first run did.
//
//   sender.send(oscPeopleBundle(station.people()));

#include "runtime/people/PeopleFrame.hpp"

#include <cstdint>
#include <vector>

namespace arcomp {

std::vector<std::uint8_t> oscPeopleBundle(const PeopleFrame& frame);

}  // namespace arcomp
