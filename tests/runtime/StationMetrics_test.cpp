#include "runtime/operator/StationMetrics.hpp"

#include <gtest/gtest.h>

namespace arcomp {

TEST(StationMetrics, histogramBucketsAreCumulativeAndCountEveryFrame) {
    StationMetrics metrics;
    metrics.recordFrame(4.0);     // <= 5 ms
    metrics.recordFrame(15.0);    // <= 16.7 ms
    metrics.recordFrame(400.0);   // <= 1 s
    metrics.recordFrame(2500.0);  // only +Inf
    const std::string text = metrics.prometheusText();
    EXPECT_NE(text.find("arcomp_frame_time_seconds_bucket{le=\"0.005\"} 1\n"), std::string::npos) << text;
    EXPECT_NE(text.find("arcomp_frame_time_seconds_bucket{le=\"0.0167\"} 2\n"), std::string::npos) << text;
    EXPECT_NE(text.find("arcomp_frame_time_seconds_bucket{le=\"1\"} 3\n"), std::string::npos) << text;
    EXPECT_NE(text.find("arcomp_frame_time_seconds_bucket{le=\"+Inf\"} 4\n"), std::string::npos) << text;
    EXPECT_NE(text.find("arcomp_frame_time_seconds_count 4\n"), std::string::npos) << text;
    EXPECT_NE(text.find("arcomp_frame_time_seconds_sum 2.919\n"), std::string::npos) << text;
}

TEST(StationMetrics, cameraFaultAndReconnectShowInBothViews) {
    StationMetrics metrics;
    metrics.setCamera("front", {SourceStatus::Streaming, ""}, 0);
    metrics.setCamera("front", {SourceStatus::Disconnected, "/dev/video0: ENODEV while streaming"}, 3);
    std::string json = metrics.statusJson();
    EXPECT_NE(json.find("\"state\":\"disconnected\""), std::string::npos) << json;
    EXPECT_NE(json.find("ENODEV while streaming"), std::string::npos) << json;
    EXPECT_NE(metrics.prometheusText().find("arcomp_camera_up{camera=\"front\"} 0\n"), std::string::npos);

    metrics.setCamera("front", {SourceStatus::Streaming, ""}, 3);
    metrics.setCamera("front", {SourceStatus::Streaming, ""}, 5);  // still the same reconnect
    const std::string text = metrics.prometheusText();
    EXPECT_NE(text.find("arcomp_camera_up{camera=\"front\"} 1\n"), std::string::npos) << text;
    EXPECT_NE(text.find("arcomp_camera_reconnects_total{camera=\"front\"} 1\n"), std::string::npos) << text;
    EXPECT_NE(text.find("arcomp_camera_dropped_frames_total{camera=\"front\"} 5\n"), std::string::npos) << text;
}

TEST(StationMetrics, statusJsonEscapesMessagesAndKeepsTheLastTenErrors) {
    StationMetrics metrics;
    for (int i = 0; i < 12; ++i) metrics.recordError("error " + std::to_string(i));
    metrics.recordError("quote \" backslash \\ newline \n tab \t bell \a");
    const std::string json = metrics.statusJson();
    EXPECT_NE(json.find("\"errors\":13"), std::string::npos) << json;
    EXPECT_EQ(json.find("\"error 2\""), std::string::npos) << "errors beyond the last ten are dropped";
    EXPECT_NE(json.find("\"error 3\""), std::string::npos) << json;
    EXPECT_NE(json.find(R"(quote \" backslash \\ newline \n tab \t bell \u0007)"), std::string::npos) << json;
}

// A camera's name comes from the config, its reason from the OS: bytes that
// are not UTF-8 become U+FFFD, and the document stays whole.
TEST(StationMetrics, statusJsonSurvivesBytesThatAreNotUtf8) {
    StationMetrics metrics;
    metrics.setCamera("cam\xff", {SourceStatus::Disconnected, "bad \xc3\x28 byte"}, 0);
    const std::string json = metrics.statusJson();
    EXPECT_NE(json.find("\"name\":\"cam\xef\xbf\xbd\""), std::string::npos) << json;
    EXPECT_NE(json.find("bad \xef\xbf\xbd( byte"), std::string::npos) << json;
    EXPECT_EQ(json.back(), '}');
}

TEST(StationMetrics, peopleAndEachOutputsStateAndCountsShowInBothViews) {
    StationMetrics metrics;
    OutputStatus osc;
    osc.kind = "osc";
    osc.target = "127.0.0.1:9000";
    osc.state = "sending";
    osc.sent = 120;
    osc.dropped = 2;
    OutputStatus mqtt;
    mqtt.kind = "mqtt";
    mqtt.target = "broker.local:1883";
    mqtt.state = "disconnected: The connection was refused.";
    mqtt.dropped = 7;
    mqtt.queued = 3;
    metrics.setPeople(4, {osc, mqtt});

    const std::string text = metrics.prometheusText();
    EXPECT_NE(text.find("arcomp_people 4\n"), std::string::npos) << text;
    EXPECT_NE(text.find("arcomp_output_messages_sent_total{output=\"osc\",target=\"127.0.0.1:9000\"} 120\n"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("arcomp_output_messages_dropped_total{output=\"mqtt\",target=\"broker.local:1883\"} 7\n"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("arcomp_output_up{output=\"osc\",target=\"127.0.0.1:9000\"} 1\n"), std::string::npos) << text;
    EXPECT_NE(text.find("arcomp_output_up{output=\"mqtt\",target=\"broker.local:1883\"} 0\n"), std::string::npos)
        << text;

    const std::string json = metrics.statusJson();
    EXPECT_NE(json.find("\"people\":4"), std::string::npos) << json;
    EXPECT_NE(json.find("{\"kind\":\"mqtt\",\"target\":\"broker.local:1883\",\"state\":\"disconnected: The "
                        "connection was refused.\",\"sent\":0,\"dropped\":7,\"queued\":3"),
              std::string::npos)
        << json;
}

TEST(StationMetrics, zonesTriggersAndCuesShowInBothViews) {
    StationMetrics metrics;
    metrics.setZones(
        {{.name = "front", .people = 2, .entries = 7}, {.name = "dino \"rex\"", .people = 0, .entries = 1}},
        {{.name = "sign", .fired = 3, .holds = true}});
    metrics.recordCue(true);
    metrics.recordCue(false);
    metrics.recordCue(false);
    const std::string text = metrics.prometheusText();
    EXPECT_NE(text.find("arcomp_zone_people{zone=\"front\"} 2\n"), std::string::npos) << text;
    EXPECT_NE(text.find("arcomp_zone_entries_total{zone=\"front\"} 7\n"), std::string::npos) << text;
    EXPECT_NE(text.find("arcomp_zone_people{zone=\"dino \\\"rex\\\"\"} 0\n"), std::string::npos) << "escaped: " << text;
    EXPECT_NE(text.find("arcomp_trigger_fired_total{trigger=\"sign\"} 3\n"), std::string::npos) << text;
    EXPECT_NE(text.find("arcomp_cues_total{result=\"accepted\"} 1\n"), std::string::npos) << text;
    EXPECT_NE(text.find("arcomp_cues_total{result=\"refused\"} 2\n"), std::string::npos) << text;
    const std::string json = metrics.statusJson();
    EXPECT_NE(json.find(R"("zones":[{"name":"front","people":2,"entries":7})"), std::string::npos) << json;
    EXPECT_NE(json.find(R"("triggers":[{"name":"sign","fired":3,"holds":true}])"), std::string::npos) << json;
    EXPECT_NE(json.find(R"("cues":{"accepted":1,"refused":2})"), std::string::npos) << json;
}

TEST(StationMetrics, eachStreamsStateBitrateDropsAndReconnectsShowInBothViews) {
    StationMetrics metrics;
    StreamStatus obs;
    obs.name = "obs";
    obs.target = "srt caller to 10.0.0.2:9000";
    obs.framesIn = 500;
    obs.dropped = 12;
    obs.packetsDropped = 40;
    obs.reconnects = 2;
    obs.kbps = 3950.5;
    StreamStatus lobby = obs;
    lobby.name = "lobby";
    lobby.state = StreamState::Retrying;
    lobby.lastError = "lobby: srtsink0: Connection does not exist";
    StreamStatus screen = obs;
    screen.name = "screen";
    screen.target = "rtsp server on 127.0.0.1:8554/screen";
    screen.clients = 3;
    metrics.setStreams({obs, lobby, screen});
    const std::string text = metrics.prometheusText();
    EXPECT_NE(text.find("arcomp_stream_up{stream=\"obs\"} 1\n"), std::string::npos) << text;
    EXPECT_NE(text.find("arcomp_stream_up{stream=\"lobby\"} 0\n"), std::string::npos) << text;
    EXPECT_NE(text.find("arcomp_stream_frames_total{stream=\"obs\"} 500\n"), std::string::npos) << text;
    EXPECT_NE(text.find("arcomp_stream_dropped_frames_total{stream=\"obs\"} 12\n"), std::string::npos) << text;
    EXPECT_NE(text.find("arcomp_stream_packets_dropped_total{stream=\"obs\"} 40\n"), std::string::npos) << text;
    EXPECT_NE(text.find("arcomp_stream_reconnects_total{stream=\"obs\"} 2\n"), std::string::npos) << text;
    EXPECT_NE(text.find("arcomp_stream_bitrate_kbps{stream=\"obs\"} 3950.5\n"), std::string::npos) << text;
    EXPECT_NE(text.find("# TYPE arcomp_stream_reconnects_total counter\n"), std::string::npos) << text;
    EXPECT_NE(text.find("arcomp_stream_clients{stream=\"screen\"} 3\n"), std::string::npos) << text;
    EXPECT_NE(text.find("arcomp_stream_clients{stream=\"obs\"} 0\n"), std::string::npos) << text;
    const std::string json = metrics.statusJson();
    EXPECT_NE(
        json.find(R"({"name":"obs","target":"srt caller to 10.0.0.2:9000","state":"streaming","frames":500,)"
                  R"("dropped":12,"packets_dropped":40,"reconnects":2,"clients":0,"kbps":3950.5,"last_error":"")"),
        std::string::npos)
        << json;
    EXPECT_NE(json.find(R"("state":"retrying")"), std::string::npos) << json;
    EXPECT_NE(json.find(R"("reconnects":2,"clients":3,)"), std::string::npos) << json;
    EXPECT_NE(json.find("Connection does not exist"), std::string::npos) << json;
}

}  // namespace arcomp
