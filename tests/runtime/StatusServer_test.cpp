#include "runtime/operator/StatusServer.hpp"

#include "../support/TempDir.hpp"
#include "graph/core/BadInput.hpp"
#include "tools/bench/probes/HttpProbe.hpp"

#include <gtest/gtest.h>
#include <httplib.h>
#include <poll.h>
#include <sys/socket.h>

#include <vector>

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
        EXPECT_NE(std::string(e.what()).find("127.0.0.1:" + std::to_string(first.port())), std::string::npos)
            << e.what();
    }
}

namespace {

// True once the server has closed the connection (EOF or reset), waiting at
// most `wait` for it.
bool closedByServer(const FileDescriptor& socket, std::chrono::milliseconds wait) {
    pollfd p{socket.get(), POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(wait.count())) <= 0) return false;
    char byte;
    return ::recv(socket.get(), &byte, 1, 0) <= 0;
}

constexpr std::chrono::milliseconds kPatience{5000};  // generous: a loaded CI machine

}  // namespace

TEST(StatusServer, aTokenFileMakesEveryRequestShowTheToken) {
    test::TempDir dir;
    const std::string token = "5f0c1d2e3a4b5c6d7e8f9a0b";
    StationMetrics metrics;
    StatusServer server(metrics, {.bind = "0.0.0.0", .port = 0, .tokenFile = dir.write("token", token + "\n")});

    const HttpProbeReply none = httpGet(server.port(), "/metrics", {.timeout = kPatience});
    EXPECT_EQ(none.status, 401) << none.error;
    EXPECT_NE(none.head.find("WWW-Authenticate: Bearer"), std::string::npos) << none.head;
    EXPECT_EQ(none.body.find("arcomp_"), std::string::npos) << none.body;

    const HttpProbeReply wrong = httpGet(
        server.port(), "/status", {.extraHeaders = "Authorization: Bearer " + token + "x\r\n", .timeout = kPatience});
    EXPECT_EQ(wrong.status, 401) << wrong.error;
    // Unknown paths are not revealed either.
    EXPECT_EQ(httpGet(server.port(), "/nothing", {.timeout = kPatience}).status, 401);

    const HttpProbeReply right = httpGet(
        server.port(), "/metrics", {.extraHeaders = "Authorization: Bearer " + token + "\r\n", .timeout = kPatience});
    EXPECT_EQ(right.status, 200) << right.error;
    EXPECT_NE(right.body.find("arcomp_frame_time_seconds"), std::string::npos) << right.body;
    EXPECT_EQ(server.counters().unauthorized, 3u);
    EXPECT_EQ(server.counters().served, 1u);
}

TEST(StatusServer, beyondLoopbackWithoutATokenFileItDoesNotStart) {
    StationMetrics metrics;
    try {
        StatusServer server(metrics, {.bind = "0.0.0.0", .port = 0});
        FAIL() << "an open endpoint on every interface started";
    } catch (const BadInput& e) {
        EXPECT_NE(std::string(e.what()).find("token_file"), std::string::npos) << e.what();
    }
}

TEST(StatusServer, idleConnectionsBeyondTheBoundsMakeRoomForAScrape) {
    StationMetrics metrics;
    StatusServer server(metrics,
                        {.port = 0, .limits = {.maxConnections = 8, .maxPerClient = 4, .requestTimeout = kPatience}});
    // 40 idle connections from four addresses, 10 each: far past both bounds.
    std::vector<FileDescriptor> idle;
    for (int i = 0; i < 40; ++i) idle.push_back(connectLoopback(server.port(), "127.0.0." + std::to_string(2 + i % 4)));

    const HttpProbeReply scrape = httpGet(server.port(), "/metrics", {.timeout = kPatience});
    EXPECT_EQ(scrape.status, 200) << scrape.error;
    // The scrape was accepted after all 40: by then at most 8 can be open.
    // The last round's evictions are closed as that round ends, which may
    // be after the reply, so closures are counted until they add up.
    std::vector<bool> closed(idle.size(), false);
    int closedCount = 0;
    for (const auto until = std::chrono::steady_clock::now() + kPatience;
         closedCount < 40 - 8 && std::chrono::steady_clock::now() < until;)
        for (std::size_t i = 0; i < idle.size(); ++i)
            if (!closed[i] && closedByServer(idle[i], std::chrono::milliseconds(1))) {
                closed[i] = true;
                ++closedCount;
            }
    EXPECT_GE(closedCount, 40 - 8);
    EXPECT_GE(server.counters().evicted, static_cast<std::uint64_t>(40 - 8));
}

TEST(StatusServer, aClientOverItsShareLosesItsOwnIdlestConnectionNotAnothers) {
    StationMetrics metrics;
    StatusServer server(metrics,
                        {.port = 0, .limits = {.maxConnections = 8, .maxPerClient = 2, .requestTimeout = kPatience}});
    const FileDescriptor first = connectLoopback(server.port(), "127.0.0.2");
    const FileDescriptor other = connectLoopback(server.port(), "127.0.0.3");
    // A request on each in turn: the server has accepted a connection once it has answered on it.
    EXPECT_EQ(httpGet(server.port(), "/status", {.from = "127.0.0.3", .timeout = kPatience}).status, 200);
    const FileDescriptor second = connectLoopback(server.port(), "127.0.0.2");
    EXPECT_EQ(httpGet(server.port(), "/status", {.from = "127.0.0.2", .timeout = kPatience}).status, 200);

    EXPECT_TRUE(closedByServer(first, kPatience));
    // Evictions close at the end of the server's round: a wrong one would
    // show within moments of `first` closing.
    EXPECT_FALSE(closedByServer(other, std::chrono::milliseconds(200)));
    EXPECT_FALSE(closedByServer(second, std::chrono::milliseconds(200)));
}

TEST(StatusServer, aClientThatNeverFinishesItsRequestIsClosedAtTheTimeout) {
    StationMetrics metrics;
    StatusServer server(metrics, {.port = 0, .limits = {.requestTimeout = std::chrono::milliseconds(200)}});
    const FileDescriptor slow = connectLoopback(server.port());
    pollfd p{slow.get(), POLLOUT, 0};
    ASSERT_EQ(::poll(&p, 1, static_cast<int>(kPatience.count())), 1);
    ASSERT_EQ(::send(slow.get(), "GET /sta", 8, MSG_NOSIGNAL), 8);
    EXPECT_TRUE(closedByServer(slow, kPatience));
    EXPECT_EQ(server.counters().timedOut, 1u);
}

TEST(StatusServer, aClientThatShutsItsSideAfterTheRequestStillGetsTheReply) {
    StationMetrics metrics;
    StatusServer server(metrics, {.port = 0});
    const FileDescriptor client = connectLoopback(server.port());
    pollfd p{client.get(), POLLOUT, 0};
    ASSERT_EQ(::poll(&p, 1, static_cast<int>(kPatience.count())), 1);
    const std::string request = "GET /status HTTP/1.0\r\n\r\n";
    ASSERT_EQ(::send(client.get(), request.data(), request.size(), MSG_NOSIGNAL), static_cast<ssize_t>(request.size()));
    ASSERT_EQ(::shutdown(client.get(), SHUT_WR), 0);  // as `nc -N` does
    std::string reply;
    char chunk[4096];
    for (;;) {
        p = {client.get(), POLLIN, 0};
        ASSERT_EQ(::poll(&p, 1, static_cast<int>(kPatience.count())), 1) << "no reply, or no end to it: " << reply;
        const ssize_t n = ::recv(client.get(), chunk, sizeof chunk, 0);
        if (n <= 0) break;
        reply.append(chunk, static_cast<std::size_t>(n));
    }
    EXPECT_EQ(reply.substr(0, 12), "HTTP/1.1 200") << reply;
    EXPECT_NE(reply.find("\"frames\""), std::string::npos) << reply;
}

TEST(StatusServer, aClientThatHangsUpMidRequestIsClosedAtOnce) {
    StationMetrics metrics;
    StatusServer server(metrics, {.port = 0, .limits = {.requestTimeout = kPatience}});
    const FileDescriptor client = connectLoopback(server.port());
    pollfd p{client.get(), POLLOUT, 0};
    ASSERT_EQ(::poll(&p, 1, static_cast<int>(kPatience.count())), 1);
    ASSERT_EQ(::send(client.get(), "GET /sta", 8, MSG_NOSIGNAL), 8);
    ASSERT_EQ(::shutdown(client.get(), SHUT_WR), 0);
    EXPECT_TRUE(closedByServer(client, kPatience));
    EXPECT_EQ(server.counters().timedOut, 0u);
}

TEST(StatusServer, garbageGetsA400AndOtherMethodsA405) {
    StationMetrics metrics;
    StatusServer server(metrics, {.port = 0});
    httplib::Client client("127.0.0.1", server.port());
    const auto post = client.Post("/status", "x", "text/plain");
    ASSERT_TRUE(post);
    EXPECT_EQ(post->status, 405);

    const FileDescriptor garbage = connectLoopback(server.port());
    pollfd p{garbage.get(), POLLOUT, 0};
    ASSERT_EQ(::poll(&p, 1, static_cast<int>(kPatience.count())), 1);
    // A TLS hello's first bytes, NULs included, then a blank line.
    const std::string hello("\x16\x03\x01\x02\x00\x01\x00\r\n\r\n", 11);
    ASSERT_EQ(::send(garbage.get(), hello.data(), hello.size(), MSG_NOSIGNAL), static_cast<ssize_t>(hello.size()));
    p = {garbage.get(), POLLIN, 0};
    ASSERT_EQ(::poll(&p, 1, static_cast<int>(kPatience.count())), 1);
    char reply[64] = {};
    ASSERT_GT(::recv(garbage.get(), reply, sizeof reply - 1, 0), 12);
    EXPECT_EQ(std::string(reply).substr(0, 12), "HTTP/1.1 400");
}

}  // namespace arcomp
