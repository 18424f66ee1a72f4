// RTSP out, served by the station on loopback and pulled by GStreamer's own
// rtspsrc, decoding through libav, and by OpenCV's FFmpeg capture: frames
// whole and in order at PSNR >= 35 dB; a
// mount with credentials plays only to a client that gives them; a client
// that quits and another that comes get the stream; two mounts share a
// port; a client that stops reading holds up neither the frame nor the
// other clients; a port another program holds is an error at start.

#include "tests/support/FreePort.hpp"
#include "tests/support/GstReceiver.hpp"
#include "tests/support/StreamFrames.hpp"
#include "tools/bench/scenes/NumberedFrames.hpp"
#include "video/pixels/VideoError.hpp"
#include "video/streams/GstRuntime.hpp"
#include "video/streams/StreamOutputs.hpp"

#include <gtest/gtest.h>
#include <opencv2/videoio.hpp>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <thread>

using namespace arcomp;

namespace {

const cv::Size kRtspPicture{320, 240};

void skipWithoutRtsp() {
    for (const char* e : {"x264enc", "rtph264pay", "rtspsrc", "rtph264depay", "avdec_h264"})
        if (!hasGstElement(e)) GTEST_SKIP() << "GStreamer element " << e << " missing";
}

StreamSpec rtsp(int port, const std::string& path, const std::string& name = "screen") {
    StreamSpec s = parseStreamUrl("rtsp://:" + std::to_string(port) + path);
    s.name = name;
    s.encoding.keyframeSeconds = 2.0;  // a client's first picture comes from the keyframe it asks for
    return s;
}

// rtspsrc over TCP, up to the H.264 stream; `options`: "user-id=... user-pw=...".
std::string rtspSource(int port, const std::string& path, const std::string& options = "") {
    return "rtspsrc location=rtsp://127.0.0.1:" + std::to_string(port) + path +
           " protocols=tcp latency=100 tcp-timeout=5000000 teardown-timeout=1000000000 " + options + " ! rtph264depay";
}

template <class Predicate>
bool eventually(Predicate done, std::chrono::seconds limit = std::chrono::seconds(10)) {
    const auto end = std::chrono::steady_clock::now() + limit;
    while (!done() && std::chrono::steady_clock::now() < end)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    return done();
}

TEST(RtspStream, aClientPullsTheCompositeInOrder) {
    skipWithoutRtsp();
    const int port = test::freeLoopbackPort(SOCK_STREAM);
    StreamOutputs out({rtsp(port, "/lobby")}, {kRtspPicture.width, kRtspPicture.height, 25.0});
    EXPECT_EQ(out.status().front().target, "rtsp://127.0.0.1:" + std::to_string(port) + "/lobby");
    test::sendNumberedFrames(out, 0, 10, kRtspPicture);  // no client yet: encoded, served to no one
    {
        test::GstReceiver rx(rtspSource(port, "/lobby"));
        for (int next = 10; next < 400 && rx.count() < 25; next += 5)
            test::sendNumberedFrames(out, next, 5, kRtspPicture);
        ASSERT_GE(rx.count(), 25u);
        test::expectNumberedInOrder(rx.frames(), kRtspPicture);
        EXPECT_GE(frameNumberOf(rx.frames().front()), 10);
        EXPECT_EQ(out.status().front().clients, 1u);
        EXPECT_EQ(out.status().front().state, StreamState::Streaming) << out.status().front().lastError;
    }
    EXPECT_TRUE(eventually([&] { return out.status().front().clients == 0; })) << "the client that left is counted";
}

// FFmpeg's client (OpenCV's capture here; ffplay, OBS and VLC's own) starts
// a new frame at every SPS, so a keyframe whose slices each carry one is
// decoded as two half pictures: every frame must come whole.
TEST(RtspStream, anFfmpegClientDecodesWholeFrames) {
    skipWithoutRtsp();
    const int port = test::freeLoopbackPort(SOCK_STREAM);
    StreamOutputs out({rtsp(port, "/ffmpeg")}, {kRtspPicture.width, kRtspPicture.height, 25.0});
    std::atomic<bool> reading{true};
    std::thread station([&] {
        for (int next = 0; reading && next < 1000; next += 5) test::sendNumberedFrames(out, next, 5, kRtspPicture);
    });
    setenv("OPENCV_FFMPEG_CAPTURE_OPTIONS", "rtsp_transport;tcp", 1);
    cv::VideoCapture client("rtsp://127.0.0.1:" + std::to_string(port) + "/ffmpeg", cv::CAP_FFMPEG,
                            {cv::CAP_PROP_OPEN_TIMEOUT_MSEC, 10000, cv::CAP_PROP_READ_TIMEOUT_MSEC, 5000});
    std::vector<cv::Mat> frames;
    for (cv::Mat f; client.isOpened() && frames.size() < 40 && client.read(f);) frames.push_back(f.clone());
    reading = false;
    station.join();
    ASSERT_EQ(frames.size(), 40u) << "OpenCV's FFmpeg capture read " << frames.size() << " frames";
    test::expectNumberedInOrder(frames, kRtspPicture);
}

TEST(RtspStream, aMountWithCredentialsPlaysOnlyToAClientThatGivesThem) {
    skipWithoutRtsp();
    const int port = test::freeLoopbackPort(SOCK_STREAM);
    StreamSpec spec = rtsp(port, "/hall");
    spec.user = "screen";
    spec.password = "second-screen-key";
    StreamOutputs out({spec}, {kRtspPicture.width, kRtspPicture.height, 25.0});
    {
        test::GstReceiver stranger(rtspSource(port, "/hall"));
        test::GstReceiver guesser(rtspSource(port, "/hall", "user-id=screen user-pw=wrong-key"));
        test::sendNumberedFrames(out, 0, 50, kRtspPicture);
        EXPECT_EQ(stranger.count(), 0u) << "a client without credentials got frames";
        EXPECT_EQ(guesser.count(), 0u) << "a client with the wrong password got frames";
        EXPECT_EQ(out.status().front().clients, 0u);
    }
    test::GstReceiver rx(rtspSource(port, "/hall", "user-id=screen user-pw=second-screen-key"));
    for (int next = 50; next < 400 && rx.count() < 10; next += 5) test::sendNumberedFrames(out, next, 5, kRtspPicture);
    ASSERT_GE(rx.count(), 10u);
    test::expectNumberedInOrder(rx.frames(), kRtspPicture);
}

TEST(RtspStream, aClientThatQuitsAndAnotherThatComesGetTheStream) {
    skipWithoutRtsp();
    const int port = test::freeLoopbackPort(SOCK_STREAM);
    StreamOutputs out({rtsp(port, "/lobby")}, {kRtspPicture.width, kRtspPicture.height, 25.0});
    int next = 0;
    int lastSeen = -1;
    {
        test::GstReceiver first(rtspSource(port, "/lobby"));
        for (; next < 400 && first.count() < 10; next += 5) test::sendNumberedFrames(out, next, 5, kRtspPicture);
        ASSERT_GE(first.count(), 10u);
        lastSeen = frameNumberOf(first.frames().back());
    }
    ASSERT_TRUE(eventually([&] { return out.status().front().clients == 0; }));
    test::sendNumberedFrames(out, next, 10, kRtspPicture);  // no one watching
    next += 10;
    test::GstReceiver second(rtspSource(port, "/lobby"));
    for (int i = 0; i < 80 && second.count() < 10; ++i, next += 5) test::sendNumberedFrames(out, next, 5, kRtspPicture);
    ASSERT_GE(second.count(), 10u) << "the second client got no stream";
    test::expectNumberedInOrder(second.frames(), kRtspPicture);
    EXPECT_GT(frameNumberOf(second.frames().front()), lastSeen);
    EXPECT_EQ(out.status().front().state, StreamState::Streaming);
}

TEST(RtspStream, twoMountsShareAPortAndAStalledClientHoldsUpNoOne) {
    skipWithoutRtsp();
    const int port = test::freeLoopbackPort(SOCK_STREAM);
    StreamOutputs out({rtsp(port, "/lobby", "lobby"), rtsp(port, "/hall", "hall")},
                      {kRtspPicture.width, kRtspPicture.height, 25.0});
    test::GstReceiver stalled(rtspSource(port, "/lobby"), test::Reading::Stalled);
    test::GstReceiver lobby(rtspSource(port, "/lobby"));
    test::GstReceiver hall(rtspSource(port, "/hall"));
    int sent = 0;
    for (; sent < 600 && (lobby.count() < 60 || hall.count() < 60); sent += 5)
        test::sendNumberedFrames(out, sent, 5, kRtspPicture);
    EXPECT_GE(lobby.count(), 60u) << "a client beside a stalled one got too little";
    EXPECT_GE(hall.count(), 60u);
    test::expectNumberedInOrder(lobby.frames(), kRtspPicture);
    test::expectNumberedInOrder(hall.frames(), kRtspPicture);
    for (const StreamStatus& s : out.status()) {
        EXPECT_EQ(s.framesIn, static_cast<std::uint64_t>(sent)) << s.name;
        EXPECT_EQ(s.state, StreamState::Streaming) << s.name << ": " << s.lastError;
    }
    EXPECT_EQ(out.status()[0].clients, 2u);
    EXPECT_EQ(out.status()[1].clients, 1u);
}

TEST(RtspStream, aPortAnotherProgramHoldsIsAnErrorAtStart) {
    skipWithoutRtsp();
    const int port = test::freeLoopbackPort(SOCK_STREAM);
    StreamOutputs first({rtsp(port, "/lobby", "first")}, {kRtspPicture.width, kRtspPicture.height, 25.0});
    try {
        StreamOutputs second({rtsp(port, "/lobby", "second")}, {kRtspPicture.width, kRtspPicture.height, 25.0});
        FAIL() << "two servers on one port";
    } catch (const VideoError& e) {
        EXPECT_NE(std::string(e.what()).find("second"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(std::to_string(port)), std::string::npos) << e.what();
    }
}

TEST(RtspStream, onePathServedTwiceOnAPortIsRefused) {
    skipWithoutRtsp();
    const int port = test::freeLoopbackPort(SOCK_STREAM);
    EXPECT_THROW(StreamOutputs({rtsp(port, "/lobby", "a"), rtsp(port, "/lobby", "b")},
                               {kRtspPicture.width, kRtspPicture.height, 25.0}),
                 VideoError);
}

}  // namespace
