#pragma once
// The config's `zones` list: named places on the floor, or in the picture
// for a camera without a calibration (runtime/zones/Zone.hpp).
//
//   zones:
//     - {name: front, polygon: [[-1, 1], [1, 1], [1, 2.5], [-1, 2.5]]}   # floor x, z in metres
//     - {name: dino, circle: {center: [2, 1.5], radius: 0.8}}            # metres
//     - {name: door, image_rect: {min: [0, 0.5], max: [0.2, 1]}}         # picture 0..1, u right, v down
//
// `enter_margin` and `leave_margin` (in the zone's units; 0.15 m on the
// floor, 0.02 of the picture by default) keep a person on the edge from
// flickering in and out. Each is checked where it is written: one shape each, a name used once, a
// polygon with area whose edges do not cross, metres only with
// camera.calibration, and a floor zone the calibrated camera sees some of.

#include "runtime/zones/Zone.hpp"

#include <optional>
#include <vector>

namespace arcomp {

class YamlMap;
struct CalibratedCamera;

// `camera`: the calibrated camera, or none; floor zones need it.
void readZoneConfig(YamlMap& root, const std::optional<CalibratedCamera>& camera, std::vector<Zone>& out);

}  // namespace arcomp
