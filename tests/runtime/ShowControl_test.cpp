// The people leave the station over real UDP on loopback and are read back
// by a real OSC receiver (liblo's parser): arcomp's address space in its
// order, TUIO 1.1 cursors in theirs, a target that does not resolve is off
// while the others go on, and a bundle too big for a datagram is counted as
// dropped, not sent cut.

#include "runtime/showcontrol/ShowControl.hpp"

#include "runtime/showcontrol/OscPeople.hpp"

#include "tests/support/OscReceiver.hpp"
#include "tests/support/TempDir.hpp"

#include <gtest/gtest.h>

using namespace arcomp;
using arcomp::test::OscReceiver;
using arcomp::test::TempDir;

namespace {

NetworkTarget loopback(const OscReceiver& rx, const std::string& where = "show_control.osc.targets[0]") {
    return {.host = "127.0.0.1", .port = rx.port(), .where = where};
}

Person personAt(int id, glm::vec2 position, glm::vec2 velocity = {0.0f, 0.0f}) {
    return {.id = id,
            .ageSeconds = 1.5,
            .seen = true,
            .position = position,
            .velocity = velocity,
            .heightMetres = 1.7f,
            .box = {10, 20, 30, 90}};
}

PeopleFrame frameAt(std::uint64_t frame, double seconds, PositionUnits units) {
    PeopleFrame f;
    f.frame = frame;
    f.seconds = seconds;
    f.units = units;
    return f;
}

std::vector<std::string> pathsAndFirstWords(const std::vector<OscReceiver::Message>& messages) {
    std::vector<std::string> out;
    for (const auto& m : messages) out.push_back(m.path + (m.types.starts_with("s") ? " " + m.s(0) : ""));
    return out;
}

}  // namespace

TEST(ShowControl, oscBundleIsTheFrameThenEnterThenEachPersonThenLeave) {
    TempDir dir;
    OscReceiver rx(dir.path());
    ShowControlConfig cfg;
    cfg.osc.targets = {loopback(rx)};
    ShowControl show(cfg);
    ASSERT_TRUE(show.problems().empty());

    PeopleFrame frame = frameAt(41, 1.64, PositionUnits::FloorMetres);
    frame.people = {personAt(2, {0.5f, -1.0f}, {0.25f, 0.0f}), personAt(3, {-1.25f, 2.0f})};
    frame.people[1].seen = false;
    frame.entered = {3};
    frame.left = {1};
    show.publish(frame);

    const auto got = rx.receive(std::chrono::seconds(2), 1);
    ASSERT_EQ(rx.datagrams(), 1u);
    EXPECT_EQ(pathsAndFirstWords(got), (std::vector<std::string>{"/arcomp/frame", "/arcomp/enter", "/arcomp/person",
                                                                 "/arcomp/person", "/arcomp/leave"}));
    EXPECT_EQ(got[0].types, "ifsi");
    EXPECT_EQ(got[0].i(0), 41);
    EXPECT_FLOAT_EQ(got[0].f(1), 1.64f);
    EXPECT_EQ(got[0].s(2), "floor_m");
    EXPECT_EQ(got[0].i(3), 2);
    EXPECT_EQ(got[1].types, "iff");
    EXPECT_EQ(got[1].i(0), 3);
    EXPECT_FLOAT_EQ(got[1].f(1), -1.25f);
    EXPECT_FLOAT_EQ(got[1].f(2), 2.0f);
    EXPECT_EQ(got[2].types, "iffffffiiiii");
    EXPECT_EQ(got[2].i(0), 2);
    EXPECT_FLOAT_EQ(got[2].f(1), 0.5f);
    EXPECT_FLOAT_EQ(got[2].f(2), -1.0f);
    EXPECT_FLOAT_EQ(got[2].f(3), 0.25f);
    EXPECT_FLOAT_EQ(got[2].f(5), 1.7f);
    EXPECT_FLOAT_EQ(got[2].f(6), 1.5f);
    EXPECT_EQ(got[2].i(7), 1);
    EXPECT_EQ(got[2].i(11), 90);
    EXPECT_EQ(got[3].i(0), 3);
    EXPECT_EQ(got[3].i(7), 0) << "person 3 is held, not seen";
    EXPECT_EQ(got[4].i(0), 1);
    EXPECT_EQ(show.outputs().at(0).sent, 1u);
    EXPECT_EQ(show.outputs().at(0).state, "sending");
}

TEST(ShowControl, oscCarriesEachPersonsZonesAndEachZonesCount) {
    TempDir dir;
    OscReceiver rx(dir.path());
    ShowControlConfig cfg;
    cfg.osc.targets = {loopback(rx)};
    ShowControl show(cfg);
    PeopleFrame frame = frameAt(3, 0.12, PositionUnits::FloorMetres);
    frame.people = {personAt(2, {0.5f, 1.0f}), personAt(5, {3.0f, 1.0f})};
    frame.people[0].zones = {0, 1};
    frame.zones = {{.name = "front", .people = 1, .entries = 4}, {.name = "dino", .people = 1, .entries = 1}};
    show.publish(frame);
    const auto got = rx.receive(std::chrono::seconds(2), 1);
    EXPECT_EQ(pathsAndFirstWords(got), (std::vector<std::string>{"/arcomp/frame", "/arcomp/person", "/arcomp/person",
                                                                 "/arcomp/zone front", "/arcomp/zone dino"}));
    ASSERT_EQ(got.size(), 5u);
    EXPECT_EQ(got[1].types, "iffffffiiiiiss");
    EXPECT_EQ(got[1].s(12), "front");
    EXPECT_EQ(got[1].s(13), "dino");
    EXPECT_EQ(got[2].types, "iffffffiiiii") << "person 5 is in no zone";
    EXPECT_EQ(got[3].types, "sii");
    EXPECT_EQ(got[3].i(1), 1);
    EXPECT_EQ(got[3].i(2), 4);
}

TEST(ShowControl, aTriggersOscMessageGoesToTheOscTargetsWithItsArgumentsAndNotToTuio) {
    TempDir dir;
    std::filesystem::create_directories(dir.path() / "osc");
    std::filesystem::create_directories(dir.path() / "tuio");
    OscReceiver osc(dir.path() / "osc"), tuio(dir.path() / "tuio");
    ShowControlConfig cfg;
    cfg.osc.targets = {loopback(osc)};
    cfg.tuio.targets = {loopback(tuio, "show_control.tuio.targets[0]")};
    ShowControl show(cfg);
    show.send({.kind = ActionKind::Osc,
               .address = "/show/cue",
               .args = {{.type = OscArgument::Type::Int, .i = 7},
                        {.type = OscArgument::Type::Float, .f = 0.5f},
                        {.type = OscArgument::Type::String, .s = "go"}}});
    const auto got = osc.receive(std::chrono::seconds(2), 1);
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0].path, "/show/cue");
    EXPECT_EQ(got[0].types, "ifs");
    EXPECT_EQ(got[0].i(0), 7);
    EXPECT_EQ(got[0].f(1), 0.5f);
    EXPECT_EQ(got[0].s(2), "go");
    EXPECT_TRUE(tuio.receive(std::chrono::milliseconds(300), 1).empty());
    EXPECT_THROW(show.send({.kind = ActionKind::Show, .object = "sign"}), std::invalid_argument);
}

TEST(ShowControl, tuioCursorsAreSourceAliveSetFseqOnTheFloorRectangle) {
    TempDir dir;
    OscReceiver rx(dir.path());
    ShowControlConfig cfg;
    cfg.tuio.targets = {loopback(rx, "show_control.tuio.targets[0]")};
    cfg.tuio.floorMin = {-4.0f, -6.0f};
    cfg.tuio.floorMax = {4.0f, 2.0f};
    ShowControl show(cfg);

    PeopleFrame frame = frameAt(7, 0.28, PositionUnits::FloorMetres);
    // 5 at the rectangle's middle walking right; 6 off it; 9 at its near left corner.
    frame.people = {personAt(5, {0.0f, -2.0f}, {0.8f, 0.0f}), personAt(6, {10.0f, 0.0f}), personAt(9, {-4.0f, 2.0f})};
    show.publish(frame);
    frame.frame = 8;
    frame.seconds = 0.32;
    frame.people[0].velocity = {0.8f, 0.4f};  // 0.05 of the rectangle a second more in y, over 0.04 s
    show.publish(frame);

    const auto got = rx.receive(std::chrono::seconds(2), 2);
    ASSERT_EQ(rx.datagrams(), 2u);
    const std::vector<std::string> order{"/tuio/2Dcur source", "/tuio/2Dcur alive", "/tuio/2Dcur set",
                                         "/tuio/2Dcur set", "/tuio/2Dcur fseq"};
    std::vector<std::string> all = pathsAndFirstWords(got), first(all.begin(), all.begin() + 5);
    EXPECT_EQ(first, order);
    EXPECT_EQ(std::vector<std::string>(all.begin() + 5, all.end()), order);
    EXPECT_EQ(got[0].s(1), "arcomp");
    EXPECT_EQ(got[1].types, "sii");
    EXPECT_EQ(got[1].i(1), 5);
    EXPECT_EQ(got[1].i(2), 9) << "6 stands off the floor rectangle";
    EXPECT_EQ(got[2].types, "sifffff");
    EXPECT_EQ(got[2].i(1), 5);
    EXPECT_FLOAT_EQ(got[2].f(2), 0.5f);
    EXPECT_FLOAT_EQ(got[2].f(3), 0.5f);
    EXPECT_FLOAT_EQ(got[2].f(4), 0.1f);
    EXPECT_FLOAT_EQ(got[2].f(5), 0.0f);
    EXPECT_FLOAT_EQ(got[2].f(6), 0.0f) << "no acceleration on a cursor's first frame";
    EXPECT_FLOAT_EQ(got[3].f(2), 0.0f);
    EXPECT_FLOAT_EQ(got[3].f(3), 1.0f);
    EXPECT_EQ(got[4].i(1), 7);
    EXPECT_NEAR(got[7].f(5), 0.05f, 1e-6f);
    EXPECT_NEAR(got[7].f(6), 0.05f / 0.04f, 1e-3f);
    EXPECT_EQ(got[9].i(1), 8);
}

TEST(ShowControl, withoutACalibrationTuioCarriesThePicturesCoordinates) {
    TempDir dir;
    OscReceiver rx(dir.path());
    ShowControlConfig cfg;
    cfg.osc.targets = {loopback(rx)};
    cfg.tuio.targets = {loopback(rx, "show_control.tuio.targets[0]")};
    ShowControl show(cfg);
    PeopleFrame frame = frameAt(1, 0.04, PositionUnits::ImageNormalised);
    frame.people = {personAt(4, {0.25f, 0.75f})};
    show.publish(frame);
    const auto got = rx.receive(std::chrono::seconds(2), 2);
    ASSERT_EQ(rx.datagrams(), 2u);
    EXPECT_EQ(got[0].s(2), "image");
    const auto set =
        std::find_if(got.begin(), got.end(), [](const auto& m) { return m.path == "/tuio/2Dcur" && m.s(0) == "set"; });
    ASSERT_NE(set, got.end());
    EXPECT_FLOAT_EQ(set->f(2), 0.25f);
    EXPECT_FLOAT_EQ(set->f(3), 0.75f);
}

TEST(ShowControl, aHostThatDoesNotResolveIsOffAndTheOtherTargetsGoOn) {
    TempDir dir;
    OscReceiver rx(dir.path());
    ShowControlConfig cfg;
    cfg.osc.targets = {{.host = "no-such-host.invalid", .port = 9000, .where = "show_control.osc.targets[0]"},
                       loopback(rx, "show_control.osc.targets[1]")};
    ShowControl show(cfg);
    ASSERT_EQ(show.problems().size(), 1u);
    EXPECT_NE(show.problems()[0].find("show_control.osc.targets[0]"), std::string::npos) << show.problems()[0];
    EXPECT_NE(show.problems()[0].find("'no-such-host.invalid' does not resolve"), std::string::npos);
    ASSERT_EQ(show.outputs().size(), 2u);
    EXPECT_TRUE(show.outputs()[0].state.starts_with("off: ")) << show.outputs()[0].state;
    EXPECT_EQ(show.outputs()[1].state, "sending");

    show.publish(frameAt(0, 0.0, PositionUnits::FloorMetres));
    rx.receive(std::chrono::seconds(2), 1);
    EXPECT_EQ(rx.datagrams(), 1u);
    EXPECT_EQ(show.outputs()[0].sent + show.outputs()[0].dropped, 0u);
    EXPECT_EQ(show.outputs()[1].sent, 1u);
}

TEST(ShowControl, aBundleTooBigForADatagramIsCountedAsDroppedNotSentCut) {
    TempDir dir;
    OscReceiver rx(dir.path());
    ShowControlConfig cfg;
    cfg.osc.targets = {loopback(rx)};
    ShowControl show(cfg);
    PeopleFrame crowd = frameAt(3, 0.12, PositionUnits::FloorMetres);
    for (int id = 0; id < 2000; ++id) crowd.people.push_back(personAt(id, {0.0f, 0.0f}));  // about 150 kB
    show.publish(crowd);
    show.publish(frameAt(4, 0.16, PositionUnits::FloorMetres));
    const auto got = rx.receive(std::chrono::seconds(2), 1);
    EXPECT_EQ(show.outputs()[0].dropped, 1u);
    EXPECT_EQ(show.outputs()[0].sent, 1u);
    EXPECT_FALSE(show.outputs()[0].lastError.empty());
    ASSERT_FALSE(got.empty());
    EXPECT_EQ(got[0].i(0), 4) << "the next frame's bundle arrives whole";
}

TEST(ShowControl, aBundleIsTaggedImmediatelySoTheSameFrameGivesTheSameBytes) {
    PeopleFrame frame = frameAt(12, 0.48, PositionUnits::FloorMetres);
    frame.people = {personAt(1, {0.5f, 2.0f})};
    const std::vector<std::uint8_t> once = oscPeopleBundle(frame), again = oscPeopleBundle(frame);
    EXPECT_EQ(once, again);
    ASSERT_GT(once.size(), 16u);
    EXPECT_EQ(std::string(once.begin(), once.begin() + 8), std::string("#bundle\0", 8));
    EXPECT_EQ(std::vector<std::uint8_t>(once.begin() + 8, once.begin() + 16),
              (std::vector<std::uint8_t>{0, 0, 0, 0, 0, 0, 0, 1}))
        << "OSC's time tag for \"immediately\"";
}
