#include "runtime/showcontrol/OscPeople.hpp"

#include "runtime/showcontrol/OscBundle.hpp"

namespace arcomp {

std::vector<std::uint8_t> oscPeopleBundle(const PeopleFrame& frame) {
    OscBundle b;
    b.add("/arcomp/frame")
        .i(static_cast<std::int32_t>(frame.frame))
        .f(static_cast<float>(frame.seconds))
        .s(unitsName(frame.units))
        .i(static_cast<std::int32_t>(frame.people.size()));
    for (const int id : frame.entered)
        if (const Person* p = findPerson(frame, id)) b.add("/arcomp/enter").i(id).f(p->position.x).f(p->position.y);
    for (const Person& p : frame.people) {
        OscBundle::Message m = b.add("/arcomp/person")
                                   .i(p.id)
                                   .f(p.position.x)
                                   .f(p.position.y)
                                   .f(p.velocity.x)
                                   .f(p.velocity.y)
                                   .f(p.heightMetres)
                                   .f(static_cast<float>(p.ageSeconds))
                                   .i(p.seen ? 1 : 0)
                                   .i(p.box.x)
                                   .i(p.box.y)
                                   .i(p.box.width)
                                   .i(p.box.height);
        // Then the names of the zones the person is in, one string each.
        for (const int z : p.zones) m.s(frame.zones[static_cast<std::size_t>(z)].name.c_str());
    }
    for (const ZoneCount& z : frame.zones)
        b.add("/arcomp/zone").s(z.name.c_str()).i(z.people).i(static_cast<std::int32_t>(z.entries));
    for (const int id : frame.left) b.add("/arcomp/leave").i(id);
    return b.bytes();
}

}  // namespace arcomp
