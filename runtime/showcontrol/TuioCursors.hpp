#pragma once
// A frame's people as TUIO 1.1 cursors (the 2Dcur profile), so that any
// TUIO client follows visitors as it follows fingers. One bundle a frame:
//   /tuio/2Dcur source s "arcomp"
//   /tuio/2Dcur alive  i id ...              every person on the floor rectangle
//   /tuio/2Dcur set    i id f x f y f X f Y f m   one each
//   /tuio/2Dcur fseq   i frame
// x, y in 0..1: with a calibrated camera the floor rectangle's (x right,
// z towards the camera downwards), a person off the rectangle is not alive;
// without one, the picture's. X, Y: velocity in those units a second; m:
// how fast that velocity changes (its length's units a second squared).
// A person's session id is their person id, never reused.
//
//   TuioCursors tuio(cfg.showControl.tuio.floorMin, cfg.showControl.tuio.floorMax);
//   sender.send(tuio.bundle(station.people()));

#include "runtime/people/PeopleFrame.hpp"

#include <glm/vec2.hpp>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace arcomp {

class TuioCursors {
public:
    TuioCursors(glm::vec2 floorMin, glm::vec2 floorMax) : floorMin_(floorMin), floorMax_(floorMax) {}
    std::vector<std::uint8_t> bundle(const PeopleFrame& frame);

private:
    struct Motion {
        glm::vec2 velocity{0.0f};
        double seconds = 0.0;
    };
    glm::vec2 floorMin_, floorMax_;
    std::unordered_map<int, Motion> previous_;  // by id: last frame's velocity, for m
};

}  // namespace arcomp
