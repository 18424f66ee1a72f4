// Who is in which zone: a person enters once inside by the enter margin
// and leaves once outside by the leave margin, so that standing on the edge
// does not flicker; a held person keeps their zones; picture zones read the
// foot point; each zone counts its people and its entries.

#include "runtime/zones/ZoneOccupancy.hpp"

#include <gtest/gtest.h>

using namespace arcomp;

namespace {

Zone square(const std::string& name, ZoneSpace space, glm::vec2 lo, glm::vec2 hi, float margin) {
    return {.name = name,
            .space = space,
            .polygon = {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}},
            .center = {},
            .radius = 0.0f,
            .enterMargin = margin,
            .leaveMargin = margin};
}

PeopleFrame walkerAt(glm::vec2 position, bool seen = true, glm::vec2 picture = {0.5f, 0.5f}) {
    PeopleFrame f;
    f.units = PositionUnits::FloorMetres;
    f.people.push_back({.id = 4,
                        .ageSeconds = 0.0,
                        .seen = seen,
                        .position = position,
                        .velocity = {},
                        .heightMetres = 0.0f,
                        .box = {},
                        .picture = picture,
                        .zones = {}});
    return f;
}

}  // namespace

TEST(ZoneOccupancy, standingOnTheEdgeDoesNotFlicker) {
    ZoneOccupancy zones({square("front", ZoneSpace::Floor, {0, 0}, {2, 2}, 0.15f)});
    const auto inFront = [&](float x) { return !zones.update(walkerAt({x, 1.0f})).people[0].zones.empty(); };
    EXPECT_FALSE(inFront(-0.5f));
    // Swaying across the edge, never 0.15 m inside: not in.
    for (const float x : {0.1f, -0.1f, 0.12f, -0.05f, 0.1f}) EXPECT_FALSE(inFront(x)) << x;
    EXPECT_TRUE(inFront(0.2f));  // 0.2 m inside: in
    // Swaying across the edge, never 0.15 m outside: still in.
    for (const float x : {0.05f, -0.1f, 0.1f, -0.14f}) EXPECT_TRUE(inFront(x)) << x;
    EXPECT_FALSE(inFront(-0.2f));  // 0.2 m outside: out
    EXPECT_EQ(zones.people().zones.at(0).entries, 1u) << "one entry, however long the swaying";
    EXPECT_EQ(zones.people().zones.at(0).people, 0);
}

TEST(ZoneOccupancy, countsEachZonesPeopleAndGivesEachPersonTheirZones) {
    ZoneOccupancy zones({square("left", ZoneSpace::Floor, {-2, 0}, {0, 2}, 0.1f),
                         square("all", ZoneSpace::Floor, {-2, 0}, {2, 2}, 0.1f),
                         square("door", ZoneSpace::Image, {0.0f, 0.5f}, {0.2f, 1.0f}, 0.02f)});
    PeopleFrame f = walkerAt({-1.0f, 1.0f}, true, {0.1f, 0.8f});
    f.people.push_back({.id = 9,
                        .ageSeconds = 0.0,
                        .seen = true,
                        .position = {1.0f, 1.0f},
                        .velocity = {},
                        .heightMetres = 0.0f,
                        .box = {},
                        .picture = {0.6f, 0.8f},
                        .zones = {}});
    const PeopleFrame& now = zones.update(f);
    EXPECT_EQ(now.people[0].zones, (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(now.people[1].zones, (std::vector<int>{1}));
    ASSERT_EQ(now.zones.size(), 3u);
    EXPECT_EQ(now.zones[0], (ZoneCount{.name = "left", .people = 1, .entries = 1}));
    EXPECT_EQ(now.zones[1], (ZoneCount{.name = "all", .people = 2, .entries = 2}));
    EXPECT_EQ(now.zones[2], (ZoneCount{.name = "door", .people = 1, .entries = 1}));
}

TEST(ZoneOccupancy, aHeldPersonKeepsTheirZonesAndFloorZonesNeedMetres) {
    ZoneOccupancy zones({square("front", ZoneSpace::Floor, {0, 0}, {2, 2}, 0.1f)});
    EXPECT_EQ(zones.update(walkerAt({1.0f, 1.0f})).people[0].zones.size(), 1u);
    // Merged with someone: the tracker holds the last place; even a jump keeps the zone.
    EXPECT_EQ(zones.update(walkerAt({5.0f, 5.0f}, false)).people[0].zones.size(), 1u);
    EXPECT_TRUE(zones.update(walkerAt({5.0f, 5.0f})).people[0].zones.empty());

    PeopleFrame picture = walkerAt({1.0f, 1.0f});
    picture.units = PositionUnits::ImageNormalised;
    ZoneOccupancy uncalibrated({square("front", ZoneSpace::Floor, {0, 0}, {2, 2}, 0.1f)});
    EXPECT_TRUE(uncalibrated.update(picture).people[0].zones.empty());
}

TEST(ZoneOccupancy, withoutZonesThePeoplePassUnchanged) {
    ZoneOccupancy none({});
    const PeopleFrame f = walkerAt({1.0f, 1.0f});
    EXPECT_EQ(none.update(f).people, f.people);
    EXPECT_TRUE(none.people().zones.empty());
}

TEST(ZoneOccupancy, eachEntryAndLeavingIsAnEventOnItsFrameAndWhoeverIsGoneLeaves) {
    ZoneOccupancy zones({square("front", ZoneSpace::Floor, {0, 0}, {2, 2}, 0.1f)});
    using Kind = ZoneEvent::Kind;
    EXPECT_TRUE(zones.update(walkerAt({-1.0f, 1.0f})).zoneEvents.empty());
    EXPECT_EQ(zones.update(walkerAt({1.0f, 1.0f})).zoneEvents,
              (std::vector<ZoneEvent>{{.kind = Kind::Enter, .zone = 0, .person = 4}}));
    EXPECT_TRUE(zones.update(walkerAt({1.5f, 1.0f})).zoneEvents.empty());
    EXPECT_EQ(zones.update(walkerAt({3.0f, 1.0f})).zoneEvents,
              (std::vector<ZoneEvent>{{.kind = Kind::Leave, .zone = 0, .person = 4}}));
    zones.update(walkerAt({1.0f, 1.0f}));
    PeopleFrame nobody;
    nobody.units = PositionUnits::FloorMetres;
    const PeopleFrame& after = zones.update(nobody);
    EXPECT_EQ(after.zoneEvents, (std::vector<ZoneEvent>{{.kind = Kind::Leave, .zone = 0, .person = 4}}))
        << "a person no longer followed leaves their zones";
    EXPECT_EQ(after.zones.at(0).people, 0);
    EXPECT_EQ(after.zones.at(0).entries, 2u);
}
