#include "runtime/StatusServer.hpp"

#include <gtest/gtest.h>
#include <httplib.h>

namespace arcomp {

TEST(StatusServer, answersStatusAndMetricsOnLoopback) {
    StationMetrics metrics;
    metrics.setConfig("configs/demo-replay.yaml");
    metrics.recordFrame(12.0);
    metrics.setCamera("replay", {SourceStatus::Error, "vtest.avi: damaged at frame 17"}, 0);
    StatusServer server(metrics, {.bind = "127.0.0.1", .port = 0});
    ASSERT_GT(server.port(), 0);

    httplib::Client client("127.0.0.1", server.port());
    const auto status = client.Get("/status");
    ASSERT_TRUE(status) << httplib::to_string(status.error());
    EXPECT_EQ(status->status, 200);
    EXPECT_EQ(status->get_header_value("Content-Type"), "application/json");
    EXPECT_NE(status->body.find("\"state\":\"error\""), std::string::npos) << status->body;
    EXPECT_NE(status->body.find("damaged at frame 17"), std::string::npos) << status->body;

    const auto prometheus = client.Get("/metrics");
    ASSERT_TRUE(prometheus);
    EXPECT_EQ(prometheus->status, 200);
    EXPECT_NE(prometheus->body.find("arcomp_camera_up{camera=\"replay\"} 0"), std::string::npos) << prometheus->body;
    EXPECT_NE(prometheus->body.find("arcomp_frame_time_seconds_count 1"), std::string::npos) << prometheus->body;

    EXPECT_EQ(client.Get("/nothing-here")->status, 404);
}

TEST(StatusServer, aBusyPortIsAnErrorThatNamesTheAddress) {
    StationMetrics metrics;
    StatusServer first(metrics, {.bind = "127.0.0.1", .port = 0});
    try {
        StatusServer second(metrics, {.bind = "127.0.0.1", .port = first.port()});
        FAIL() << "a second server bound the same port";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("127.0.0.1:" + std::to_string(first.port())), std::string::npos) << e.what();
    }
}

} // namespace arcomp
