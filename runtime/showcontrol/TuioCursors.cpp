#include "runtime/showcontrol/TuioCursors.hpp"

#include "runtime/showcontrol/OscBundle.hpp"

#include <glm/geometric.hpp>

namespace arcomp {

std::vector<std::uint8_t> TuioCursors::bundle(const PeopleFrame& frame) {
    struct Cursor {
        int id;
        glm::vec2 at, velocity;
        float acceleration;
    };
    const bool onFloor = frame.units == PositionUnits::FloorMetres;
    const glm::vec2 span = onFloor ? floorMax_ - floorMin_ : glm::vec2(1.0f);
    const glm::vec2 origin = onFloor ? floorMin_ : glm::vec2(0.0f);
    std::vector<Cursor> cursors;
    std::unordered_map<int, Motion> now;
    for (const Person& p : frame.people) {
        const glm::vec2 at = (p.position - origin) / span;
        if (at.x < 0.0f || at.y < 0.0f || at.x > 1.0f || at.y > 1.0f) continue;
        const glm::vec2 velocity = p.velocity / span;
        float acceleration = 0.0f;
        if (const auto before = previous_.find(p.id);
            before != previous_.end() && frame.seconds > before->second.seconds)
            acceleration = glm::length(velocity - before->second.velocity) /
                           static_cast<float>(frame.seconds - before->second.seconds);
        cursors.push_back({p.id, at, velocity, acceleration});
        now[p.id] = {velocity, frame.seconds};
    }
    previous_ = std::move(now);

    OscBundle b;
    b.add("/tuio/2Dcur").s("source").s("arcomp");
    OscBundle::Message alive = b.add("/tuio/2Dcur").s("alive");
    for (const Cursor& c : cursors) alive.i(c.id);
    for (const Cursor& c : cursors)
        b.add("/tuio/2Dcur").s("set").i(c.id).f(c.at.x).f(c.at.y).f(c.velocity.x).f(c.velocity.y).f(c.acceleration);
    b.add("/tuio/2Dcur").s("fseq").i(static_cast<std::int32_t>(frame.frame));
    return b.bytes();
}

}  // namespace arcomp
