// Cues from show control: OSC and JSON decoded without trusting a byte
// (malformed packets, bundles, wrong types and unknown verbs are refused
// with why); a listener on loopback that hears only the senders it allows,
// fed by real liblo senders; the config's checks of where it listens.

#include "runtime/config/StationConfig.hpp"
#include "runtime/showcontrol/CueDecode.hpp"
#include "runtime/showcontrol/OscCueListener.hpp"

#include "tests/support/ConfigIssues.hpp"
#include "tests/support/TempDir.hpp"

#include <gtest/gtest.h>
#include <lo/lo.h>

#include <arpa/inet.h>
#include <sys/socket.h>
#include <unistd.h>

#include <random>
#include <thread>

using namespace arcomp;
using arcomp::test::TempDir;

namespace {

// An OSC message as liblo writes it.
std::vector<std::uint8_t> oscMessage(const char* path, const std::vector<const char*>& strings, int number = -1) {
    lo_message m = lo_message_new();
    for (const char* s : strings) lo_message_add_string(m, s);
    if (number >= 0) lo_message_add_int32(m, number);
    std::size_t size = 0;
    void* bytes = lo_message_serialise(m, path, nullptr, &size);
    std::vector<std::uint8_t> out(static_cast<std::uint8_t*>(bytes), static_cast<std::uint8_t*>(bytes) + size);
    free(bytes);
    lo_message_free(m);
    return out;
}

// Sends `datagram` to the listener from a socket bound to `from` (any 127.x.y.z reaches loopback).
void sendFrom(const char* from, int port, const std::vector<std::uint8_t>& datagram) {
    const int fd = socket(AF_INET, SOCK_DGRAM, 0);
    sockaddr_in local{};
    local.sin_family = AF_INET;
    inet_pton(AF_INET, from, &local.sin_addr);
    ASSERT_EQ(bind(fd, reinterpret_cast<sockaddr*>(&local), sizeof local), 0) << from;
    sockaddr_in to{};
    to.sin_family = AF_INET;
    to.sin_port = htons(static_cast<std::uint16_t>(port));
    inet_pton(AF_INET, "127.0.0.1", &to.sin_addr);
    sendto(fd, datagram.data(), datagram.size(), 0, reinterpret_cast<sockaddr*>(&to), sizeof to);
    close(fd);
}

// Polls until `count` datagrams have been read or a second has passed.
std::vector<ReceivedCue> pollFor(OscCueListener& in, std::size_t count) {
    std::vector<ReceivedCue> got;
    for (int i = 0; i < 100 && got.size() < count; ++i) {
        in.poll(got);
        if (got.size() < count) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return got;
}

CueInputConfig listenOnLoopback(std::vector<std::string> allow = {}) {
    CueInputConfig c;
    c.osc = true;
    c.listen.port = 0;
    c.allow = std::move(allow);
    return c;
}

}  // namespace

TEST(CueDecode, oscCuesNameTheirVerbAndTakeStrings) {
    const CueDecoded play = decodeOscCue(oscMessage("/arcomp/cue/play", {"dino", "roar"}));
    ASSERT_TRUE(play.cue) << play.error;
    EXPECT_EQ(play.cue->action.kind, ActionKind::Play);
    EXPECT_EQ(play.cue->action.object, "dino");
    EXPECT_EQ(play.cue->action.animation, "roar");
    const CueDecoded reload = decodeOscCue(oscMessage("/arcomp/cue/reload", {}));
    ASSERT_TRUE(reload.cue) << reload.error;
    EXPECT_EQ(reload.cue->kind, Cue::Kind::Reload);
    EXPECT_EQ(decodeOscCue(oscMessage("/arcomp/cue/snapshot", {})).cue->action.kind, ActionKind::Snapshot);
    EXPECT_EQ(decodeOscCue(oscMessage("/arcomp/cue/hide", {"sign"})).cue->action.kind, ActionKind::Hide);
}

TEST(CueDecode, malformedPacketsAndWrongCuesAreRefusedWithWhy) {
    const auto refusal = [](const std::vector<std::uint8_t>& bytes) {
        const CueDecoded d = decodeOscCue(bytes);
        EXPECT_FALSE(d.cue);
        return d.error;
    };
    EXPECT_NE(refusal({}).find("not an OSC packet"), std::string::npos);
    EXPECT_NE(refusal({'/', 'a', 'b'}).find("not an OSC packet"), std::string::npos) << "no terminating zero";
    std::vector<std::uint8_t> cut = oscMessage("/arcomp/cue/show", {"sign"});
    cut.resize(cut.size() - 4);
    EXPECT_NE(refusal(cut).find("malformed OSC message"), std::string::npos);
    std::vector<std::uint8_t> bundle = {'#', 'b', 'u', 'n', 'd', 'l', 'e', 0, 0, 0, 0, 0, 0, 0, 0, 1};
    EXPECT_NE(refusal(bundle).find("OSC bundle"), std::string::npos);
    EXPECT_NE(refusal(oscMessage("/show/go", {})).find("is not a cue; expected /arcomp/cue/<verb>"), std::string::npos);
    EXPECT_NE(refusal(oscMessage("/arcomp/cue/show", {}, 3)).find("has type 'i'; cues take strings"),
              std::string::npos);
    EXPECT_NE(refusal(oscMessage("/arcomp/cue/explode", {"sign"})).find("unknown cue 'explode'"), std::string::npos);
    EXPECT_NE(refusal(oscMessage("/arcomp/cue/show", {})).find("expected an object's name"), std::string::npos);
    EXPECT_NE(refusal(oscMessage("/arcomp/cue/hide", {"a", "b"})).find("expected an object's name"), std::string::npos);
    EXPECT_NE(refusal(oscMessage("/arcomp/cue/reload", {"now"})).find("takes no arguments"), std::string::npos);
    // Random bytes and every cut of a real cue: refused, never a crash.
    std::mt19937 random(7);
    for (int i = 0; i < 2000; ++i) {
        std::vector<std::uint8_t> noise(random() % 64);
        for (auto& b : noise) b = static_cast<std::uint8_t>(random());
        if (i % 3 == 0 && noise.size() > 12) std::copy_n("/arcomp/cue/", 12, noise.begin());
        (void)decodeOscCue(noise);
    }
    const std::vector<std::uint8_t> whole = oscMessage("/arcomp/cue/play", {"dino", "roar"});
    for (std::size_t n = 0; n < whole.size(); ++n) EXPECT_FALSE(decodeOscCue({whole.data(), n}).cue) << n;
}

TEST(CueDecode, jsonCuesTakeTheSameWords) {
    const CueDecoded play = decodeJsonCue(R"({"cue": "play", "object": "dino", "animation": "roar"})");
    ASSERT_TRUE(play.cue) << play.error;
    EXPECT_EQ(play.cue->action.animation, "roar");
    EXPECT_EQ(decodeJsonCue(R"({"cue": "reload"})").cue->kind, Cue::Kind::Reload);
    EXPECT_NE(decodeJsonCue("{broken").error.find("not a JSON object"), std::string::npos);
    EXPECT_NE(decodeJsonCue(R"({"cue": "show", "objekt": "x"})").error.find("unknown key 'objekt'"), std::string::npos);
    EXPECT_NE(decodeJsonCue(R"({"cue": 3})").error.find("'cue' is not a string"), std::string::npos);
    EXPECT_NE(decodeJsonCue(R"({"object": "x"})").error.find(R"(no "cue")"), std::string::npos);
}

TEST(OscCueListener, hearsCuesOnLoopbackFromARealLibloSender) {
    OscCueListener in(listenOnLoopback());
    ASSERT_GT(in.port(), 0);
    lo_address to = lo_address_new("127.0.0.1", std::to_string(in.port()).c_str());
    lo_send(to, "/arcomp/cue/show", "s", "sign");
    lo_send(to, "/arcomp/cue/show", "i", 4);
    lo_address_free(to);
    const std::vector<ReceivedCue> got = pollFor(in, 2);
    ASSERT_EQ(got.size(), 2u);
    ASSERT_TRUE(got[0].cue) << got[0].error;
    EXPECT_EQ(got[0].cue->action.object, "sign");
    EXPECT_TRUE(got[0].sender.starts_with("127.0.0.1:")) << got[0].sender;
    EXPECT_FALSE(got[1].cue);
    EXPECT_EQ(in.counts().received, 2u);
    EXPECT_EQ(in.counts().malformed, 1u);
    std::vector<ReceivedCue> none;
    in.poll(none);
    EXPECT_TRUE(none.empty()) << "nothing waiting: back at once";
}

TEST(OscCueListener, aSenderThatIsNotAllowedIsDroppedUndecodedAndCounted) {
    OscCueListener in(listenOnLoopback({"127.0.0.2"}));
    sendFrom("127.0.0.1", in.port(), oscMessage("/arcomp/cue/hide", {"sign"}));
    sendFrom("127.0.0.2", in.port(), oscMessage("/arcomp/cue/hide", {"sign"}));
    const std::vector<ReceivedCue> got = pollFor(in, 2);
    ASSERT_EQ(got.size(), 2u);
    const auto fromOne = got[0].sender.starts_with("127.0.0.1:") ? got[0] : got[1];
    const auto fromTwo = got[0].sender.starts_with("127.0.0.2:") ? got[0] : got[1];
    EXPECT_FALSE(fromOne.cue);
    EXPECT_NE(fromOne.error.find("sender 127.0.0.1 is not in show_control.cues.osc.allow"), std::string::npos)
        << fromOne.error;
    ASSERT_TRUE(fromTwo.cue) << fromTwo.error;
    EXPECT_EQ(in.counts().refusedSender, 1u);
}

TEST(CueInputConfig, listensOnLoopbackUnlessToldAndBeyondItOnlyWithAnAllowList) {
    TempDir dir;
    const StationConfig plain = loadStationConfig(dir.write("a.yaml", R"(scene: {objects: [{shape: box}]}
show_control:
  cues: {osc: {listen: 9100}}
)"));
    EXPECT_TRUE(plain.showControl.cues.osc);
    EXPECT_EQ(plain.showControl.cues.listen.text(), "127.0.0.1:9100");
    EXPECT_EQ(plain.showControl.cues.snapshotFolder, dir.path() / "snapshots");
    const std::string text = R"(scene: {objects: [{shape: box}]}
show_control:
  cues:
    osc: {listen: "0.0.0.0:9100"}
    mqtt: true
)";
    const auto issues = test::configIssues(dir.write("b.yaml", text));
    EXPECT_TRUE(test::hasIssue(issues, 4, "beyond loopback, needs allow")) << test::describe(issues);
    EXPECT_TRUE(test::hasIssue(issues, 4, "needs show_control.mqtt")) << test::describe(issues);
    const auto badAllow = test::configIssues(dir.write("c.yaml", R"(scene: {objects: [{shape: box}]}
show_control:
  cues: {osc: {listen: "0.0.0.0:9100", allow: [10.0.0.300]}}
)"));
    EXPECT_TRUE(test::hasIssue(badAllow, 3, "'10.0.0.300' is not an IPv4 address")) << test::describe(badAllow);
}
