// SRT out, against GStreamer's own srtsrc on loopback, decoding through
// libav: a caller reaches a listening receiver and a listener serves a
// calling one, frames in order at PSNR >= 35 dB; a passphrase keeps a
// receiver without it out; a receiver that quits and comes back gets the
// stream again; one that stops reading makes the stream drop, counted.

#include "tests/support/FreePort.hpp"
#include "tests/support/GstReceiver.hpp"
#include "tests/support/StreamFrames.hpp"
#include "tools/bench/scenes/NumberedFrames.hpp"
#include "video/pixels/VideoError.hpp"
#include "video/streams/GstRuntime.hpp"
#include "video/streams/StreamOutputs.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

using namespace arcomp;

namespace {

const cv::Size kPicture{320, 240};

void skipWithoutSrt() {
    for (const char* e : {"x264enc", "srtsink", "srtsrc", "avdec_h264"})
        if (!hasGstElement(e)) GTEST_SKIP() << "GStreamer element " << e << " missing";
}

StreamSpec srt(const std::string& url) {
    StreamSpec s = parseStreamUrl(url);
    s.name = "test";
    s.encoding.keyframeSeconds = 0.4;  // a receiver joining waits less
    return s;
}

TEST(SrtStream, aCallerReachesAListeningReceiver) {
    skipWithoutSrt();
    const int port = test::freeLoopbackPort(SOCK_DGRAM);
    test::GstReceiver rx(test::srtSource("srt://127.0.0.1:" + std::to_string(port) + "?mode=listener"));
    StreamOutputs out({srt("srt://127.0.0.1:" + std::to_string(port))}, {kPicture.width, kPicture.height, 25.0});
    test::sendNumberedFrames(out, 0, 60, kPicture);
    ASSERT_TRUE(rx.waitForFrames(20)) << rx.count() << " frames came";
    test::expectNumberedInOrder(rx.frames(), kPicture);
    const StreamStatus s = out.status().front();
    EXPECT_EQ(s.framesIn, 60u);
    EXPECT_EQ(s.state, StreamState::Streaming) << s.lastError;
    EXPECT_GT(s.bytes, 0u);
}

TEST(SrtStream, aListenerServesACallingReceiverAndNeedsItsPassphrase) {
    skipWithoutSrt();
    const int port = test::freeLoopbackPort(SOCK_DGRAM);
    StreamSpec spec = srt("srt://:" + std::to_string(port) + "?mode=listener");
    spec.passphrase = "lobby-screen-key";
    EXPECT_EQ(spec.host, "127.0.0.1") << "a listener binds to loopback unless told";
    StreamOutputs out({spec}, {kPicture.width, kPicture.height, 25.0});
    const std::string uri = "srt://127.0.0.1:" + std::to_string(port);
    test::GstReceiver stranger(test::srtSource(uri, "passphrase=not-the-key-at-all"));
    test::sendNumberedFrames(out, 0, 40, kPicture);
    EXPECT_EQ(stranger.count(), 0u) << "a receiver without the passphrase got frames";
    stranger.stop();
    test::GstReceiver rx(test::srtSource(uri, "passphrase=lobby-screen-key"));
    test::sendNumberedFrames(out, 40, 60, kPicture);
    ASSERT_TRUE(rx.waitForFrames(10)) << rx.count() << " frames came";
    test::expectNumberedInOrder(rx.frames(), kPicture);
    EXPECT_GE(frameNumberOf(rx.frames().front()), 40);
}

TEST(SrtStream, aReceiverThatQuitsAndComesBackGetsTheStreamAgain) {
    skipWithoutSrt();
    const int port = test::freeLoopbackPort(SOCK_DGRAM);
    const std::string listen = test::srtSource("srt://127.0.0.1:" + std::to_string(port) + "?mode=listener");
    auto first = std::make_unique<test::GstReceiver>(listen);
    StreamOutputs out({srt("srt://127.0.0.1:" + std::to_string(port))}, {kPicture.width, kPicture.height, 25.0});
    test::sendNumberedFrames(out, 0, 40, kPicture);
    ASSERT_TRUE(first->waitForFrames(10));
    first.reset();  // the receiver quits
    // The stream notices (a write to a closed connection fails) and retries.
    int next = 40;
    for (; next < 40 + 25 * 20 && out.status().front().state != StreamState::Retrying; next += 5)
        test::sendNumberedFrames(out, next, 5, kPicture);
    ASSERT_EQ(out.status().front().state, StreamState::Retrying) << "the lost receiver was not noticed";
    EXPECT_FALSE(out.status().front().lastError.empty());
    test::GstReceiver second(listen);
    for (int i = 0; i < 100 && second.count() < 10; ++i, next += 5) test::sendNumberedFrames(out, next, 5, kPicture);
    ASSERT_GE(second.count(), 10u) << "the stream did not come back";
    test::expectNumberedInOrder(second.frames(), kPicture);
    EXPECT_GT(frameNumberOf(second.frames().front()), 40);
    EXPECT_GE(out.status().front().reconnects, 1u);
    EXPECT_EQ(out.status().front().state, StreamState::Streaming);
}

// A receiver that hangs: gst-launch in a process of its own, stopped with
// SIGSTOP, so that it neither reads nor acknowledges. SRT gives up the
// packets that are too late (counted), then the connection; the stream
// goes on retrying and the frames meanwhile are dropped, counted; push()
// never waits for any of it.
TEST(SrtStream, aReceiverThatHangsMakesTheStreamDropCountedNotWait) {
    skipWithoutSrt();
    if (std::system("command -v gst-launch-1.0 >/dev/null") != 0) GTEST_SKIP() << "gst-launch-1.0 not installed";
    const int port = test::freeLoopbackPort(SOCK_DGRAM);
    const std::string uri = "uri=srt://127.0.0.1:" + std::to_string(port) + "?mode=listener";
    const pid_t receiver = fork();
    ASSERT_GE(receiver, 0);
    if (receiver == 0) {
        execlp("gst-launch-1.0", "gst-launch-1.0", "-q", "srtsrc", uri.c_str(), "!", "fakesink",
               static_cast<char*>(nullptr));
        _exit(127);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(500));  // its listener binds
    StreamOutputs out({srt("srt://127.0.0.1:" + std::to_string(port))}, {kPicture.width, kPicture.height, 25.0});
    test::sendNumberedFrames(out, 0, 25, kPicture);
    const StreamStatus before = out.status().front();
    kill(receiver, SIGSTOP);
    int sent = 25;
    bool noticed = false;
    for (; sent < 25 + 25 * 15 && !noticed; sent += 5) {
        test::sendNumberedFrames(out, sent, 5, kPicture);
        noticed = out.status().front().state == StreamState::Retrying;
    }
    test::sendNumberedFrames(out, sent, 25, kPicture);  // while it retries
    sent += 25;
    kill(receiver, SIGKILL);
    waitpid(receiver, nullptr, 0);
    const StreamStatus s = out.status().front();
    EXPECT_EQ(s.framesIn, static_cast<std::uint64_t>(sent));
    EXPECT_GT(s.packetsDropped, 0u) << "SRT gave up no packet though the receiver acknowledged none";
    EXPECT_TRUE(noticed) << "the hung receiver's connection was not given up";
    EXPECT_GT(s.dropped, before.dropped + 5) << "frames while the stream has no receiver are dropped, counted";
    EXPECT_FALSE(s.lastError.empty());
}

TEST(SrtStream, aListenerWhosePortIsTakenIsAnErrorAtStart) {
    skipWithoutSrt();
    const int port = test::freeLoopbackPort(SOCK_DGRAM);
    StreamOutputs first({srt("srt://:" + std::to_string(port) + "?mode=listener")},
                        {kPicture.width, kPicture.height, 25.0});
    try {
        StreamOutputs second({srt("srt://:" + std::to_string(port) + "?mode=listener")},
                             {kPicture.width, kPicture.height, 25.0});
        FAIL() << "two listeners on one port";
    } catch (const VideoError& e) {
        EXPECT_NE(std::string(e.what()).find("test"), std::string::npos) << e.what();
    }
}

TEST(StreamSpec, urlsAreReadOrRefusedWithWhatWasExpected) {
    const StreamSpec caller = parseStreamUrl("srt://192.168.1.20:9000");
    EXPECT_EQ(caller.host, "192.168.1.20");
    EXPECT_EQ(caller.port, 9000);
    EXPECT_FALSE(caller.listener);
    const StreamSpec everywhere = parseStreamUrl("srt://0.0.0.0:9001?mode=listener");
    EXPECT_TRUE(everywhere.listener);
    EXPECT_FALSE(isLoopbackHost(everywhere.host));
    const StreamSpec rtsp = parseStreamUrl("rtsp://:8554/lobby");
    EXPECT_EQ(rtsp.protocol, StreamProtocol::Rtsp);
    EXPECT_EQ(rtsp.host, "127.0.0.1");
    EXPECT_EQ(rtsp.path, "/lobby");
    for (const char* bad :
         {"udp://1.2.3.4:5", "srt://host", "srt://host:0", "srt://host:70000", "srt://:9000", "srt://h:9/x",
          "srt://h:9?mode=rendezvous", "rtsp://:8554", "rtsp://:8554/", "srt://h:9x"}) {
        EXPECT_THROW(parseStreamUrl(bad), std::invalid_argument) << bad;
    }
    try {
        parseStreamUrl("srt://:9000");
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("a caller needs the host"), std::string::npos) << e.what();
    }
}

}  // namespace
