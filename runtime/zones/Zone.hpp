#pragma once
// A named place where visitors are counted and their events start: a
// polygon or a circle on the floor (metres, the calibration's floor frame:
// x and z), or a rectangle in the picture (0..1, u right, v down) for a
// camera without a calibration. Values only.
//
//   Zone front{.name = "front", .space = ZoneSpace::Floor,
//              .polygon = {{-1, 1}, {1, 1}, {1, 2.5f}, {-1, 2.5f}}, .center = {}, .radius = 0.0f,
//              .enterMargin = 0.15f, .leaveMargin = 0.15f};
//   bool in = signedDistance(front, {0.0f, 2.0f}) < 0.0f;   // true

#include <glm/vec2.hpp>

#include <string>
#include <vector>

namespace arcomp {

enum class ZoneSpace { Floor, Image };

struct Zone {
    std::string name;
    ZoneSpace space = ZoneSpace::Floor;
    std::vector<glm::vec2> polygon;  // corners in order; empty for a circle
    glm::vec2 center{0.0f};          // a circle's, when radius > 0
    float radius = 0.0f;
    // Hysteresis, in the zone's units: a person enters once this far inside
    // the edge and leaves once this far outside it, so that someone
    // standing on the edge does not flicker in and out.
    float enterMargin = 0.0f, leaveMargin = 0.0f;
};

// The margins a zone gets when the config gives none: 15 cm on the floor,
// 2 % of the picture.
float defaultMargin(ZoneSpace space);

// How far `point` lies outside the zone's edge, in the zone's units;
// negative inside. Enter and leave margins compare against it.
float signedDistance(const Zone& zone, glm::vec2 point);

// Why a polygon cannot be a zone (fewer than 3 corners, no area, edges that
// cross), or empty when it can.
std::string polygonProblem(const std::vector<glm::vec2>& polygon);

// Points spread over the zone, its corners and inside, for checks such as
// "can the camera see any of it".
std::vector<glm::vec2> samplePoints(const Zone& zone, int perSide = 8);

}  // namespace arcomp
