#include "runtime/zones/ZoneOccupancy.hpp"

#include <algorithm>

namespace arcomp {

ZoneOccupancy::ZoneOccupancy(std::vector<Zone> zones) : zones_(std::move(zones)) {
    for (const Zone& z : zones_) counts_.push_back({.name = z.name, .people = 0, .entries = 0});
}

const PeopleFrame& ZoneOccupancy::update(const PeopleFrame& people) {
    now_ = people;
    now_.zoneEvents.clear();
    if (zones_.empty()) return now_;
    for (ZoneCount& c : counts_) c.people = 0;
    // Whoever is no longer followed leaves every zone they were in, in id order.
    std::vector<int> gone;
    for (const auto& [id, in] : inside_)
        if (!findPerson(now_, id)) gone.push_back(id);
    std::sort(gone.begin(), gone.end());
    for (const int id : gone)
        for (std::size_t z = 0; z < zones_.size(); ++z)
            if (inside_.at(id)[z]) now_.zoneEvents.push_back({ZoneEvent::Kind::Leave, static_cast<int>(z), id});
    std::unordered_map<int, std::vector<bool>> inside;
    for (Person& p : now_.people) {
        std::vector<bool> in(zones_.size(), false);
        if (const auto known = inside_.find(p.id); known != inside_.end()) in = known->second;
        if (p.seen)
            for (std::size_t z = 0; z < zones_.size(); ++z) {
                const Zone& zone = zones_[z];
                if (zone.space == ZoneSpace::Floor && now_.units != PositionUnits::FloorMetres) continue;
                const float d = signedDistance(zone, zone.space == ZoneSpace::Floor ? p.position : p.picture);
                const bool was = in[z];
                in[z] = was ? d <= zone.leaveMargin : d < -zone.enterMargin;
                if (in[z] && !was) ++counts_[z].entries;
                if (in[z] != was)
                    now_.zoneEvents.push_back(
                        {in[z] ? ZoneEvent::Kind::Enter : ZoneEvent::Kind::Leave, static_cast<int>(z), p.id});
            }
        p.zones.clear();
        for (std::size_t z = 0; z < zones_.size(); ++z)
            if (in[z]) {
                p.zones.push_back(static_cast<int>(z));
                ++counts_[z].people;
            }
        inside[p.id] = std::move(in);
    }
    inside_ = std::move(inside);
    now_.zones = counts_;
    return now_;
}

}  // namespace arcomp
