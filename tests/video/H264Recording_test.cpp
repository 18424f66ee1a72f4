// H.264 recordings through GStreamer: what is written decodes (through
// OpenCV's FFmpeg, a reader of its own) to the frames given, in order and
// at PSNR >= 35 dB; an MP4 is readable while it is still written; a queue
// with no room drops and counts instead of waiting; a missing element or a
// file that cannot be written is an error naming it.

#include "tests/support/TempDir.hpp"
#include "tests/support/VideoPsnr.hpp"
#include "tools/bench/scenes/NumberedFrames.hpp"
#include "video/pixels/VideoError.hpp"
#include "video/streams/GstRuntime.hpp"
#include "video/streams/H264Recording.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <chrono>
#include <thread>

using namespace arcomp;

namespace {

const cv::Size kSize{320, 240};

void pushNumbered(H264Pipeline& p, int from, int count) {
    cv::Mat rgba;
    for (int i = from; i < from + count; ++i) {
        cv::cvtColor(numberedFrame(i, kSize), rgba, cv::COLOR_BGR2RGBA);
        p.push(rgba.data);
    }
}

struct Decoded {
    std::vector<int> numbers;
    double worstPsnr = 1e9;
};

Decoded decode(const std::filesystem::path& file) {
    Decoded d;
    cv::VideoCapture in(file.string(), cv::CAP_FFMPEG);
    cv::Mat f;
    while (in.read(f)) {
        const int n = frameNumberOf(f);
        d.numbers.push_back(n);
        if (n >= 0) d.worstPsnr = std::min(d.worstPsnr, arcomp::test::videoPsnr(f, numberedFrame(n, kSize)));
    }
    return d;
}

std::vector<int> upTo(int count) {
    std::vector<int> v(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) v[static_cast<std::size_t>(i)] = i;
    return v;
}

void skipWithoutEncoder() {
    if (!hasGstElement("x264enc")) GTEST_SKIP() << "x264enc missing (gstreamer1.0-plugins-ugly not installed)";
}

void expectDecodesToTheFramesGiven(const char* extension) {
    test::TempDir dir;
    const auto file = dir.path() / (std::string("show") + extension);
    ASSERT_TRUE(isH264Container(file));
    {
        auto rec = openH264Recording(file, {}, {kSize.width, kSize.height, 25.0}, WhenFull::Wait);
        EXPECT_EQ(rec->encoder(), "x264enc");
        pushNumbered(*rec, 0, 40);
        rec->close();
        EXPECT_EQ(rec->state(), PipelineState::Closed) << rec->error();
        EXPECT_EQ(rec->dropped(), 0u);
        EXPECT_EQ(rec->framesEncoded(), 40u);
        EXPECT_GT(rec->bytesEncoded(), 1000u);
    }
    const Decoded d = decode(file);
    EXPECT_EQ(d.numbers, upTo(40));
    EXPECT_GE(d.worstPsnr, 35.0);
}

TEST(H264Recording, anMp4DecodesToTheFramesGivenInOrder) {
    skipWithoutEncoder();
    expectDecodesToTheFramesGiven(".mp4");
}

TEST(H264Recording, aMatroskaFileDecodesToTheFramesGivenInOrder) {
    skipWithoutEncoder();
    expectDecodesToTheFramesGiven(".mkv");
}

TEST(H264Recording, anMp4IsReadableWhileItIsWritten) {
    skipWithoutEncoder();
    test::TempDir dir;
    const auto file = dir.path() / "live.mp4";
    auto rec = openH264Recording(file, {}, {kSize.width, kSize.height, 25.0}, WhenFull::Wait);
    pushNumbered(*rec, 0, 120);  // four fragments of a second and a bit
    // The encoder works on its own thread: wait (for the event, not a
    // time) until the first fragments reach the file.
    Decoded d;
    for (int tries = 0; tries < 200 && d.numbers.size() < 50; ++tries) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        d = decode(file);
    }
    EXPECT_EQ(rec->state(), PipelineState::Running);
    ASSERT_GE(d.numbers.size(), 50u) << "complete fragments readable before close(); read " << d.numbers.size();
    EXPECT_EQ(std::vector<int>(d.numbers.begin(), d.numbers.begin() + 50), upTo(50));
    rec->close();
    EXPECT_EQ(decode(file).numbers, upTo(120));
}

// identity's sleep stands in for an encoder or a network slower than the
// frames: the queue fills and the frames it has no room for are dropped at
// once and counted, and every frame taken is written.
TEST(H264Recording, aFullQueueDropsAndCountsInsteadOfWaiting) {
    skipWithoutEncoder();
    test::TempDir dir;
    const auto file = dir.path() / "slow.mkv";
    H264Settings settings;
    H264Pipeline slow(
        file.string(), settings, {kSize.width, kSize.height, 25.0},
        {{"identity", {{"sleep-time", "200000"}}}, {"matroskamux"}, {"filesink", {{"location", file.string()}}}},
        WhenFull::Drop, 2);
    pushNumbered(slow, 0, 60);
    EXPECT_EQ(slow.framesIn(), 60u);
    EXPECT_GT(slow.dropped(), 30u) << "60 frames pushed at once into a queue of 2 behind a 5 fps consumer";
    slow.close(30.0);
    EXPECT_EQ(slow.state(), PipelineState::Closed) << slow.error();
    const Decoded d = decode(file);
    EXPECT_EQ(d.numbers.size(), 60u - slow.dropped());
    EXPECT_TRUE(std::is_sorted(d.numbers.begin(), d.numbers.end()));
    EXPECT_EQ(d.numbers.front(), 0);
}

TEST(H264Recording, aMissingElementIsNamedWithItsPackage) {
    skipWithoutEncoder();
    test::TempDir dir;
    try {
        H264Pipeline p("x", {}, {kSize.width, kSize.height, 25.0}, {{"nosuchmux"}}, WhenFull::Drop);
        FAIL() << "built a pipeline with an element that does not exist";
    } catch (const VideoError& e) {
        EXPECT_NE(std::string(e.what()).find("nosuchmux"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("missing"), std::string::npos) << e.what();
    }
    H264Settings elsewhere;
    elsewhere.encoder = "nosuchh264enc";
    const EncoderChoice c = chooseH264Encoder(elsewhere.encoder);
    EXPECT_EQ(c.element, "x264enc");
    EXPECT_NE(c.warning.find("nosuchh264enc"), std::string::npos) << c.warning;
}

TEST(H264Recording, aFileThatCannotBeWrittenIsAnErrorNamingIt) {
    skipWithoutEncoder();
    try {
        openH264Recording("/proc/arcomp/show.mp4", {}, {kSize.width, kSize.height, 25.0}, WhenFull::Wait);
        FAIL() << "opened a recording under /proc";
    } catch (const VideoError& e) {
        EXPECT_NE(std::string(e.what()).find("/proc/arcomp/show.mp4"), std::string::npos) << e.what();
    }
}

}  // namespace
