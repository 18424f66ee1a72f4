// The people to a real mosquitto broker on loopback, read back by a real
// MQTT client: the topics, the rate in video time, enter and leave at
// QoS 1; and the faults, checked by what is counted: a broker that is not
// there, one that goes away mid-run and comes back, credentials that
// cannot be read or are refused, and none of them a secret in the status.

#include "runtime/showcontrol/ShowControl.hpp"

#include "tests/support/MosquittoBroker.hpp"
#include "tests/support/MqttSubscriber.hpp"
#include "tests/support/TempDir.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <thread>

using namespace arcomp;
using arcomp::test::MosquittoBroker;
using arcomp::test::MqttSubscriber;
using arcomp::test::TempDir;

namespace {

MqttOutputConfig brokerAt(int port, const std::string& prefix) {
    MqttOutputConfig c;
    c.enabled = true;
    c.broker = {.host = "127.0.0.1", .port = port, .where = "show_control.mqtt.broker"};
    c.topicPrefix = prefix;
    return c;
}

// Frame `i` at 25 fps; `ids` standing, all in zone "front", `entered` and
// `left` as given.
PeopleFrame frameWith(std::uint64_t i, const std::vector<int>& ids, std::vector<int> entered = {},
                      std::vector<int> left = {}) {
    PeopleFrame f;
    f.frame = i;
    f.seconds = static_cast<double>(i) / 25.0;
    f.units = PositionUnits::FloorMetres;
    for (const int id : ids) {
        Person p;
        p.id = id;
        p.seen = true;
        p.position = {0.5f * static_cast<float>(id), 2.0f};
        p.zones = {0};
        f.people.push_back(p);
    }
    f.zones = {{.name = "front", .people = static_cast<int>(ids.size()), .entries = 1}};
    f.entered = std::move(entered);
    f.left = std::move(left);
    return f;
}

// Polls `mqtt`'s status until `done` holds (the client's thread moves it) or 10 s pass.
bool eventually(const MqttPeople& mqtt, const std::function<bool(const MqttStatus&)>& done) {
    for (int i = 0; i < 200; ++i) {
        if (done(mqtt.status())) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return done(mqtt.status());
}

std::size_t countOn(const std::vector<MqttSubscriber::Message>& got, const std::string& topic) {
    return static_cast<std::size_t>(
        std::count_if(got.begin(), got.end(), [&](const auto& m) { return m.topic == topic; }));
}

#define REQUIRE_MOSQUITTO()                                                                                            \
    if (!MosquittoBroker::installed()) GTEST_SKIP() << MosquittoBroker::kBinary << " absent (Debian's mosquitto)"

}  // namespace

TEST(MqttPeople, peopleAtTheRateInVideoTimeAndEnterAndLeaveAtQos1) {
    REQUIRE_MOSQUITTO();
    TempDir dir;
    MosquittoBroker broker(dir.path());
    MqttSubscriber sub(broker.port(), "hall/+/#");
    MqttOutputConfig cfg = brokerAt(broker.port(), "hall/entrance");
    cfg.rateHz = 5.0;
    MqttPeople mqtt(cfg);
    ASSERT_TRUE(eventually(mqtt, [](const MqttStatus& s) { return s.connected; })) << mqtt.status().state;

    // One second of video: person 3 enters at frame 2 and is gone at frame 20.
    for (std::uint64_t i = 0; i < 25; ++i)
        mqtt.publish(i < 2     ? frameWith(i, {})
                     : i == 2  ? frameWith(i, {3}, {3})
                     : i < 20  ? frameWith(i, {3})
                     : i == 20 ? frameWith(i, {}, {}, {3})
                               : frameWith(i, {}));
    const auto got = sub.waitFor(
        [](const auto& m) { return countOn(m, "hall/entrance/people") >= 5 && countOn(m, "hall/entrance/leave") >= 1; },
        std::chrono::seconds(5));
    EXPECT_EQ(countOn(got, "hall/entrance/people"), 5u) << "5 a second of video, at 0, 0.2, ... 0.8 s";
    ASSERT_EQ(countOn(got, "hall/entrance/enter"), 1u);
    ASSERT_EQ(countOn(got, "hall/entrance/leave"), 1u);
    for (const auto& m : got) {
        const nlohmann::json j = nlohmann::json::parse(m.payload, nullptr, false);
        if (m.topic == "hall/entrance/enter") {
            EXPECT_EQ(m.qos, 1);
            EXPECT_EQ(j["id"], 3);
            EXPECT_EQ(j["frame"], 2);
            EXPECT_EQ(j["units"], "floor_m");
            EXPECT_FLOAT_EQ(j["x"].get<float>(), 1.5f);
            EXPECT_EQ(j["zones"], nlohmann::json::array({"front"}));
        } else if (m.topic == "hall/entrance/leave") {
            EXPECT_EQ(m.qos, 1);
            EXPECT_EQ(j["id"], 3);
            EXPECT_EQ(j["frame"], 20);
        } else if (m.topic == "hall/entrance/people" && j["frame"] == 5) {
            EXPECT_DOUBLE_EQ(j["seconds"].get<double>(), 0.2);
            ASSERT_EQ(j["people"].size(), 1u);
            EXPECT_EQ(j["people"][0]["id"], 3);
            EXPECT_EQ(j["people"][0]["zones"], nlohmann::json::array({"front"}));
            EXPECT_EQ(j["zones"], nlohmann::json::parse(R"([{"name": "front", "people": 1, "entries": 1}])"));
        } else if (m.topic == "hall/entrance/state") {
            EXPECT_EQ(m.payload, "online");
        }
    }
    EXPECT_EQ(mqtt.status().dropped, 0u);
}

TEST(MqttPeople, aTriggersMessageGoesToItsOwnTopicAtQos1) {
    REQUIRE_MOSQUITTO();
    TempDir dir;
    MosquittoBroker broker(dir.path());
    MqttSubscriber sub(broker.port(), "show/#");
    MqttPeople mqtt(brokerAt(broker.port(), "hall/entrance"));
    ASSERT_TRUE(eventually(mqtt, [](const MqttStatus& s) { return s.connected; })) << mqtt.status().state;
    mqtt.publishMessage("show/lights", "scene 3");
    const auto got = sub.waitFor([](const auto& m) { return countOn(m, "show/lights") >= 1; }, std::chrono::seconds(5));
    ASSERT_EQ(countOn(got, "show/lights"), 1u);
    const auto m = std::find_if(got.begin(), got.end(), [](const auto& m) { return m.topic == "show/lights"; });
    EXPECT_EQ(m->payload, "scene 3");
    EXPECT_EQ(m->qos, 1);
}

TEST(MqttPeople, cuesOnTheCueTopicWaitForTheFrameInOrder) {
    REQUIRE_MOSQUITTO();
    TempDir dir;
    MosquittoBroker broker(dir.path());
    MqttSubscriber show(broker.port(), "hall/entrance/state");
    MqttPeople mqtt(brokerAt(broker.port(), "hall/entrance"), "hall/entrance/cue");
    // Subscribed once connected: the retained "online" follows the subscription.
    show.waitFor([](const auto& m) { return countOn(m, "hall/entrance/state") >= 1; }, std::chrono::seconds(5));
    ASSERT_TRUE(eventually(mqtt, [](const MqttStatus& s) { return s.connected; })) << mqtt.status().state;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the SUBSCRIBE reaches the broker
    show.publish("hall/entrance/cue", R"({"cue": "show", "object": "sign"})");
    show.publish("hall/entrance/other", "not a cue");
    show.publish("hall/entrance/cue", "{broken");
    std::vector<std::string> cues;
    for (int i = 0; i < 100 && cues.size() < 2; ++i) {
        for (std::string& c : mqtt.takeCues()) cues.push_back(std::move(c));
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    ASSERT_EQ(cues.size(), 2u);
    EXPECT_EQ(cues[0], R"({"cue": "show", "object": "sign"})");
    EXPECT_EQ(cues[1], "{broken") << "handed on as it came; the decoder refuses it";
}

TEST(MqttPeople, withNoBrokerTheFramesGoOnEventsAreHeldToTheBoundAndSentWhenItComes) {
    REQUIRE_MOSQUITTO();
    TempDir dir;
    const int port = arcomp::test::freeLoopbackPort();
    MqttOutputConfig cfg = brokerAt(port, "hall");
    cfg.eventQueue = 3;
    MqttPeople mqtt(cfg);
    // 250 frames (10 s of video, 50 people messages due) and five entries, with nobody to take them.
    for (std::uint64_t i = 0; i < 250; ++i)
        mqtt.publish(i < 5 ? frameWith(i, {int(i) + 1}, {int(i) + 1}) : frameWith(i, {}));
    MqttStatus away = mqtt.status();
    EXPECT_FALSE(away.connected);
    EXPECT_EQ(away.queued, 3u) << "held up to the bound";
    EXPECT_EQ(away.dropped, 50u + 2u) << "every people message due, and the two oldest events";
    EXPECT_EQ(away.sent, 0u);

    MosquittoBroker broker(dir.path(), "", "", port);
    ASSERT_TRUE(eventually(mqtt, [](const MqttStatus& s) { return s.connected && s.queued == 0; }))
        << mqtt.status().state;
    EXPECT_EQ(mqtt.status().sent, 3u) << "the held events, once the broker is there";
    EXPECT_EQ(mqtt.status().reconnects, 0u) << "its first connection";
}

TEST(MqttPeople, aBrokerThatGoesAwayMidRunIsReconnectedAndGetsWhatWasHeld) {
    REQUIRE_MOSQUITTO();
    TempDir dir;
    MosquittoBroker broker(dir.path());
    MqttPeople mqtt(brokerAt(broker.port(), "hall"));
    ASSERT_TRUE(eventually(mqtt, [](const MqttStatus& s) { return s.connected; })) << mqtt.status().state;
    mqtt.publish(frameWith(0, {1}, {1}));
    EXPECT_EQ(mqtt.status().sent, 2u) << "an enter and the people";

    broker.stop();
    ASSERT_TRUE(eventually(mqtt, [](const MqttStatus& s) { return !s.connected; }));
    EXPECT_TRUE(mqtt.status().state.starts_with("disconnected")) << mqtt.status().state;
    mqtt.publish(frameWith(25, {}, {}, {1}));
    EXPECT_EQ(mqtt.status().queued, 1u) << "the leave waits";
    EXPECT_EQ(mqtt.status().dropped, 1u) << "the people message due at 1 s";

    broker.start();
    ASSERT_TRUE(eventually(mqtt, [](const MqttStatus& s) { return s.connected && s.queued == 0; }))
        << mqtt.status().state;
    EXPECT_EQ(mqtt.status().reconnects, 1u);
    EXPECT_EQ(mqtt.status().sent, 3u);
}

TEST(MqttPeople, credentialsComeFromFilesAndNeverShowInTheStatus) {
    REQUIRE_MOSQUITTO();
    TempDir dir;
    MosquittoBroker broker(dir.path(), "station-7", "s3cret-Pa55");
    MqttOutputConfig cfg = brokerAt(broker.port(), "hall");
    cfg.usernameFile = dir.write("user", "station-7\n");
    cfg.passwordFile = dir.write("password", "s3cret-Pa55\n");
    MqttPeople good(cfg);
    ASSERT_TRUE(eventually(good, [](const MqttStatus& s) { return s.connected; })) << good.status().state;

    cfg.passwordFile = dir.write("wrong", "guess\n");
    ShowControlConfig show;
    show.mqtt = cfg;
    ShowControl refused(show);
    std::string state;
    for (int i = 0; i < 100 && !state.starts_with("disconnected: "); ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        state = refused.outputs().at(0).state;
    }
    EXPECT_NE(state.find("not authorised"), std::string::npos) << state;
    for (const OutputStatus& o : refused.outputs()) {
        EXPECT_EQ(o.state.find("guess"), std::string::npos);
        EXPECT_EQ(o.target.find("station-7"), std::string::npos);
    }
}

TEST(MqttPeople, aCredentialsFileThatCannotBeReadTurnsTheOutputOffAndSaysWhich) {
    TempDir dir;
    ShowControlConfig show;
    show.mqtt = brokerAt(arcomp::test::freeLoopbackPort(), "hall");
    show.mqtt.usernameFile = dir.write("user", "station-7\n");
    show.mqtt.passwordFile = dir.path() / "a-folder";  // exists, but is no file to read
    std::filesystem::create_directories(show.mqtt.passwordFile);
    ShowControl control(show);
    ASSERT_EQ(control.problems().size(), 1u);
    EXPECT_NE(control.problems()[0].find("show_control.mqtt.password_file: cannot read"), std::string::npos)
        << control.problems()[0];
    ASSERT_EQ(control.outputs().size(), 1u);
    EXPECT_EQ(control.outputs()[0].kind, "mqtt");
    EXPECT_TRUE(control.outputs()[0].state.starts_with("off: ")) << control.outputs()[0].state;
    control.publish(frameWith(0, {1}, {1}));  // and the station goes on
}
