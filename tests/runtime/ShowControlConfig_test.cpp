// The config's show_control section: targets as "host:port", TUIO's floor
// rectangle, and every mistake reported at its line with what was expected.

#include "runtime/config/StationConfig.hpp"

#include "tests/support/BoxStation.hpp"
#include "tests/support/ConfigIssues.hpp"
#include "tests/support/TempDir.hpp"

#include <gtest/gtest.h>

using namespace arcomp;
using arcomp::test::TempDir;

TEST(ShowControlConfig, absentSectionSendsNothing) {
    TempDir dir;
    const StationConfig cfg = loadStationConfig(dir.write("s.yaml", test::kBoxStation));
    EXPECT_TRUE(cfg.showControl.osc.targets.empty());
    EXPECT_TRUE(cfg.showControl.tuio.targets.empty());
}

TEST(ShowControlConfig, readsTargetsAndTheFloorRectangle) {
    TempDir dir;
    const StationConfig cfg = loadStationConfig(dir.write("s.yaml", std::string(test::kBoxStation) + R"(show_control:
  osc: {targets: ["127.0.0.1:9000", "lighting.local:7000"]}
  tuio:
    targets: ["[::1]:3333"]
    floor: {min: [-4, -6], max: [4, 3]}
)"));
    ASSERT_EQ(cfg.showControl.osc.targets.size(), 2u);
    EXPECT_EQ(cfg.showControl.osc.targets[0].host, "127.0.0.1");
    EXPECT_EQ(cfg.showControl.osc.targets[0].port, 9000);
    EXPECT_EQ(cfg.showControl.osc.targets[1].text(), "lighting.local:7000");
    EXPECT_EQ(cfg.showControl.osc.targets[1].where, "show_control.osc.targets[1]");
    ASSERT_EQ(cfg.showControl.tuio.targets.size(), 1u);
    EXPECT_EQ(cfg.showControl.tuio.targets[0].host, "::1");
    EXPECT_EQ(cfg.showControl.tuio.floorMin, glm::vec2(-4.0f, -6.0f));
    EXPECT_EQ(cfg.showControl.tuio.floorMax, glm::vec2(4.0f, 3.0f));
}

TEST(ShowControlConfig, reportsEveryMistakeWithItsLine) {
    TempDir dir;
    const auto issues = test::configIssues(dir.write("s.yaml", std::string(test::kBoxStation) + R"(show_control:
  osc:
    targets:
      - "127.0.0.1"
      - "host:99999"
      - ":9000"
      - [127.0.0.1, 9000]
  tuio:
    targets: "127.0.0.1:3333"
    floor: {min: [4, 0], max: [-4, 3]}
  midi: {}
)"));
    // kBoxStation is 7 lines; show_control starts at line 8.
    EXPECT_TRUE(test::hasIssue(issues, 11, "'127.0.0.1' is not a target; expected \"host:port\""))
        << test::describe(issues);
    EXPECT_TRUE(test::hasIssue(issues, 12, "'host:99999' is not a target")) << test::describe(issues);
    EXPECT_TRUE(test::hasIssue(issues, 13, "':9000' is not a target")) << test::describe(issues);
    EXPECT_TRUE(test::hasIssue(issues, 14, "targets[3]: expected \"host:port\" as one string"))
        << test::describe(issues);
    EXPECT_TRUE(test::hasIssue(issues, 16, "show_control.tuio.targets: expected a list")) << test::describe(issues);
    EXPECT_TRUE(test::hasIssue(issues, 17, "max must exceed min")) << test::describe(issues);
    EXPECT_TRUE(test::hasIssue(issues, 18, "midi")) << test::describe(issues);
}

TEST(ShowControlConfig, readsTheMqttOutputWithCredentialFilesBesideTheConfig) {
    TempDir dir;
    dir.write("secrets/user", "station-7\n");
    dir.write("secrets/password", "pw\n");
    const StationConfig cfg = loadStationConfig(dir.write("s.yaml", std::string(test::kBoxStation) + R"(show_control:
  mqtt:
    broker: "broker.local:8883"
    topic_prefix: museum/hall-2
    rate_hz: 2
    username_file: secrets/user
    password_file: secrets/password
    event_queue: 50
)"));
    const MqttOutputConfig& m = cfg.showControl.mqtt;
    EXPECT_TRUE(m.enabled);
    EXPECT_EQ(m.broker.text(), "broker.local:8883");
    EXPECT_EQ(m.topicPrefix, "museum/hall-2");
    EXPECT_DOUBLE_EQ(m.rateHz, 2.0);
    EXPECT_EQ(m.eventQueue, 50);
    EXPECT_EQ(m.passwordFile, (dir.path() / "secrets/password").lexically_normal());
}

TEST(ShowControlConfig, mqttMistakesAreReportedWithTheirLines) {
    TempDir dir;
    dir.write("user", "station-7\n");
    const auto issues = test::configIssues(dir.write("s.yaml", std::string(test::kBoxStation) + R"(show_control:
  mqtt:
    broker: "broker.local"
    topic_prefix: "museum/#"
    username_file: user
    rate_hz: 0
    tls: {ca_file: missing-ca.pem}
)"));
    const std::string all = test::describe(issues);
    EXPECT_NE(all.find("show_control.mqtt.broker: 'broker.local' is not a target"), std::string::npos) << all;
    EXPECT_NE(all.find("topic_prefix: 'museum/#' cannot start a topic"), std::string::npos) << all;
    EXPECT_TRUE(test::hasIssue(issues, 14, "missing-ca.pem")) << all;
    EXPECT_TRUE(test::hasIssue(issues, 13, "rate_hz")) << all;
    EXPECT_NE(all.find("username_file and password_file come together"), std::string::npos) << all;
}
