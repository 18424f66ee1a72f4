// A replay that streams over SRT, as an operator reviewing an installation
// runs it: a real receiver (GStreamer's srtsrc, decoding with libav) gets
// the composited frames, in order and as the PNGs show them; with no
// receiver at all, every PNG is still written and the stream's drops are
// said, not failed.

#include "tests/support/BoxStation.hpp"
#include "tests/support/FreePort.hpp"
#include "tests/support/GstReceiver.hpp"
#include "tests/support/Shell.hpp"
#include "tests/support/TempDir.hpp"
#include "tests/support/VideoPsnr.hpp"
#include "tools/bench/scenes/NumberedFrames.hpp"
#include "video/streams/GstRuntime.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include <cstdio>

using arcomp::test::TempDir;
namespace fs = std::filesystem;

namespace {

void skipWithoutSrtElements() {
    for (const char* e : {"x264enc", "srtsink", "srtsrc", "avdec_h264", "mpegtsmux"})
        if (!arcomp::hasGstElement(e)) GTEST_SKIP() << "GStreamer element " << e << " missing";
}

fs::path streamingStation(const TempDir& dir, const fs::path& input, int port) {
    return dir.write("station.yaml", std::string(arcomp::test::kBoxStation) + "video:\n  path: " + input.string() +
                                         "\noutput:\n  streams:\n    - name: screen\n      url: srt://127.0.0.1:" +
                                         std::to_string(port) + "\n");
}

std::size_t pngsWrittenIn(const fs::path& dir) {
    std::size_t n = 0;
    for (const auto& e : fs::directory_iterator(dir)) n += e.path().extension() == ".png";
    return n;
}

TEST(StreamReplay, aReceiverGetsTheCompositedFramesInOrder) {
    skipWithoutSrtElements();
    TempDir dir;
    const fs::path input = arcomp::writeNumberedVideo(dir.path() / "numbered.avi", 100, {320, 240});
    const int port = arcomp::test::freeLoopbackPort(SOCK_DGRAM);
    arcomp::test::GstReceiver rx(arcomp::test::srtSource("srt://127.0.0.1:" + std::to_string(port) + "?mode=listener"));
    const auto r = arcomp::test::arcompCommand("replay " + streamingStation(dir, input, port).string() + " --out " +
                                               (dir.path() / "out").string());
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("stream screen (srt caller to 127.0.0.1:" + std::to_string(port) + "): 100 frames"),
              std::string::npos)
        << r.out;
    ASSERT_TRUE(rx.waitForFrames(10)) << rx.count() << " frames came; " << r.out;
    int last = -1;
    for (const cv::Mat& f : rx.frames()) {
        const int n = arcomp::frameNumberOf(f);
        ASSERT_GT(n, last) << "in order";
        char name[32];
        std::snprintf(name, sizeof name, "frame-%06d.png", n);
        const cv::Mat composited = cv::imread((dir.path() / "out" / name).string(), cv::IMREAD_COLOR);
        ASSERT_FALSE(composited.empty()) << name;
        EXPECT_GE(arcomp::test::videoPsnr(f, composited), 35.0) << "dB, frame " << n;
        last = n;
    }
}

TEST(StreamReplay, withNoReceiverEveryFrameIsStillWrittenAndTheDropsAreSaid) {
    skipWithoutSrtElements();
    TempDir dir;
    const fs::path input = arcomp::writeNumberedVideo(dir.path() / "numbered.avi", 60, {320, 240});
    const int nobody = arcomp::test::freeLoopbackPort(SOCK_DGRAM);
    const auto r = arcomp::test::arcompCommand("replay " + streamingStation(dir, input, nobody).string() + " --out " +
                                               (dir.path() / "out").string());
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(pngsWrittenIn(dir.path() / "out"), 60u);
    unsigned frames = 0, dropped = 0;
    const auto line = r.out.find("stream screen (");
    ASSERT_NE(line, std::string::npos) << r.out;
    ASSERT_EQ(std::sscanf(r.out.c_str() + r.out.find("): ", line), "): %u frames, %u dropped", &frames, &dropped), 2)
        << r.out;
    EXPECT_EQ(frames, 60u);
    EXPECT_GT(dropped, 0u) << r.out;
}

}  // namespace
