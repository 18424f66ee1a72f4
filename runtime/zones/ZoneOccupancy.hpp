#pragma once
// Who is in which zone, frame by frame: each person's zones, each zone's
// count and entries, and the frame's entries and leavings, added to the
// people of a frame (runtime/people/PeopleFrame.hpp) before they are
// published. A person no longer followed leaves their zones.
//
//   ZoneOccupancy zones(cfg.zones);
//   const PeopleFrame& now = zones.update(floorPeople.update(...));   // each frame
//   for (const ZoneCount& z : now.zones) std::printf("%s: %d\n", z.name.c_str(), z.people);
//
// A person enters a zone once inside it by the zone's enter margin and
// leaves once outside by its leave margin, so that someone on the edge does
// not flicker. A person held but not seen keeps their zones. Floor zones
// read positions in metres; picture zones the foot point in the picture.

#include "runtime/people/PeopleFrame.hpp"
#include "runtime/zones/Zone.hpp"

#include <unordered_map>
#include <vector>

namespace arcomp {

class ZoneOccupancy {
public:
    explicit ZoneOccupancy(std::vector<Zone> zones);

    const PeopleFrame& update(const PeopleFrame& people);
    const PeopleFrame& people() const { return now_; }
    const std::vector<Zone>& zones() const { return zones_; }

private:
    std::vector<Zone> zones_;
    std::unordered_map<int, std::vector<bool>> inside_;  // person id -> per zone
    std::vector<ZoneCount> counts_;
    PeopleFrame now_;
};

}  // namespace arcomp
