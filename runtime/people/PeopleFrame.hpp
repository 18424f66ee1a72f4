#pragma once
// The visitors of one frame, as the station's outputs publish them: who is
// there, where they stand and how they move, who entered and who left.
// The station fills one per frame (runtime/people/FloorPeople.hpp); OSC,
// TUIO and MQTT read it. Values only: an output may keep a copy.
//
//   const PeopleFrame& now = station.people();
//   for (const Person& p : now.people)
//       std::printf("#%d at %.2f %.2f (%s)\n", p.id, p.position.x, p.position.y, unitsName(now.units));
//
// With a calibrated camera, positions are on the floor in metres (the
// calibration's floor frame: x and z, +y up); without one, in the picture,
// normalised to 0..1 (u right, v down), and every message says which.

#include <glm/glm.hpp>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace arcomp {

enum class PositionUnits { FloorMetres, ImageNormalised };
// "floor_m" or "image": the word messages carry.
const char* unitsName(PositionUnits units);

struct PixelBox {
    int x = 0, y = 0, width = 0, height = 0;  // frame pixels
    bool operator==(const PixelBox&) const = default;
};

struct Person {
    int id = 0;               // the tracker's: kept while the person is followed, never reused
    double ageSeconds = 0.0;  // video time since the frame the person entered
    // false: not seen in this frame (hidden, or walking merged with someone)
    // but still followed; position and velocity are the last seen.
    bool seen = false;
    glm::vec2 position{0.0f};   // floor (x, z) in metres, or picture (u, v) in 0..1
    glm::vec2 velocity{0.0f};   // position's units per second
    float heightMetres = 0.0f;  // estimated; 0 when unknown (no calibration, head out of the picture)
    PixelBox box;               // in the picture, where last seen
    glm::vec2 picture{0.0f};    // the foot point in the picture, 0..1 (u right, v down), where last seen
    std::vector<int> zones{};   // indices into PeopleFrame::zones of the zones the person is in, ascending

    bool operator==(const Person&) const = default;
};

// One configured zone this frame (runtime/zones/ZoneOccupancy.hpp).
struct ZoneCount {
    std::string name;
    int people = 0;             // in it now
    std::uint64_t entries = 0;  // people who entered it since the station started

    bool operator==(const ZoneCount&) const = default;
};

// A person entering or leaving a zone, on the frame it happened.
struct ZoneEvent {
    enum class Kind { Enter, Leave };
    Kind kind = Kind::Enter;
    int zone = 0;    // index into PeopleFrame::zones
    int person = 0;  // id

    bool operator==(const ZoneEvent&) const = default;
};
// "enter" or "leave": the word messages and the event log carry.
inline const char* kindName(ZoneEvent::Kind kind) { return kind == ZoneEvent::Kind::Enter ? "enter" : "leave"; }

struct PeopleFrame {
    std::uint64_t frame = 0;  // the station's frame number, from 0
    double seconds = 0.0;     // video time: the file's own in replay, so that a replay repeats
    PositionUnits units = PositionUnits::ImageNormalised;
    std::vector<Person> people;         // in the order of their ids
    std::vector<int> entered;           // ids in `people` for the first time this frame
    std::vector<int> left;              // ids in the previous frame's `people` and not in this one's
    std::vector<ZoneCount> zones;       // per configured zone, in the config's order; empty without zones
    std::vector<ZoneEvent> zoneEvents;  // this frame's: people no longer followed first, then by id and zone
};

// The person with `id` in `frame`; null when there is none.
inline const Person* findPerson(const PeopleFrame& frame, int id) {
    const auto at = std::lower_bound(frame.people.begin(), frame.people.end(), id,
                                     [](const Person& p, int wanted) { return p.id < wanted; });
    return at != frame.people.end() && at->id == id ? &*at : nullptr;
}

}  // namespace arcomp
