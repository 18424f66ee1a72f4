// Faults a replaying station meets and survives, through the CLI in a
// child process: the disk filling while frames are written, and a video
// damaged part-way through. Camera loss, stalls, bad reloads and a busy
// status port are covered where those parts are tested (V4l2Source,
// FallbackSource, StationRunner, StatusServer).

#include "../support/ChildProcess.hpp"
#include "../support/TempDir.hpp"
#include "tests/support/BoxStation.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include <fstream>

using namespace arcomp::test;
namespace fs = std::filesystem;

namespace {

const char* const kFaultStation = arcomp::test::kBoxStation;

// `flat` frames of one grey (their PNGs are a few kB), then `noisy` frames
// of random pixels (their PNGs are tens of kB).
fs::path writeClip(const fs::path& file, int flat, int noisy) {
    cv::VideoWriter out(file.string(), cv::CAP_FFMPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 25.0, {160, 120});
    EXPECT_TRUE(out.isOpened());
    cv::RNG rng(11);  // the same clip every run
    for (int i = 0; i < flat + noisy; ++i) {
        cv::Mat f(120, 160, CV_8UC3, cv::Scalar(120, 120, 120));
        if (i >= flat) rng.fill(f, cv::RNG::UNIFORM, 0, 256);
        out.write(f);
    }
    return file;
}

struct Written {
    int readable = 0;
    int unreadable = 0;
    int partial = 0;  // leftovers of a write that failed
};

Written writtenIn(const fs::path& dir) {
    Written w;
    if (!fs::exists(dir)) return w;
    for (const auto& e : fs::directory_iterator(dir)) {
        if (e.path().extension() == ".part") ++w.partial;
        if (e.path().extension() != ".png") continue;
        cv::imread(e.path().string(), cv::IMREAD_UNCHANGED).empty() ? ++w.unreadable : ++w.readable;
    }
    return w;
}

}  // namespace

// RLIMIT_FSIZE stands in for a full disk (a tmpfs needs root): small PNGs
// still fit, large ones fail with EFBIG part-way through their write.
TEST(ReplayFaults, diskFullIsReportedTheReplayGoesOnAndWrittenFramesStayReadable) {
    TempDir dir;
    const fs::path clip = writeClip(dir.path() / "clip.avi", 6, 6);
    const fs::path station = dir.write("station.yaml", kFaultStation);
    const fs::path out = dir.path() / "out";
    const ChildResult r = runChild({ARCOMP_BINARY, "replay", station.string(), "--video", clip.string(), "--out",
                                    out.string(), "--log-level", "error"},
                                   {.fileSizeLimit = 24 * 1024});
    ASSERT_FALSE(r.crashed()) << r.output;
    EXPECT_EQ(r.code, 1) << "missing frames make the replay a failure\n" << r.output;
    EXPECT_NE(r.output.find("replayed 12 frames"), std::string::npos) << "every frame was composited\n" << r.output;
    EXPECT_NE(r.output.find("6 of 12 frames could not be written"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("File too large"), std::string::npos) << "the system's reason is passed on\n" << r.output;
    const Written w = writtenIn(out);
    EXPECT_EQ(w.readable, 6);
    EXPECT_EQ(w.unreadable, 0) << "no half-written image under a frame's name";
    EXPECT_EQ(w.partial, 0) << "failed writes are cleaned up";
}

TEST(ReplayFaults, videoCutOffMidReplayEndsCleanlyWithTheFramesBefore) {
    TempDir dir;
    const fs::path clip = writeClip(dir.path() / "clip.avi", 40, 0);
    const auto size = fs::file_size(clip);
    fs::resize_file(clip, size * 6 / 10);
    const fs::path station = dir.write("station.yaml", kFaultStation);
    const fs::path out = dir.path() / "out";
    const ChildResult r = runChild({ARCOMP_BINARY, "replay", station.string(), "--video", clip.string(), "--out",
                                    out.string(), "--log-level", "error"});
    ASSERT_FALSE(r.crashed()) << r.output;
    EXPECT_EQ(r.code, 0) << r.output;
    const Written w = writtenIn(out);
    EXPECT_GT(w.readable, 10) << r.output;
    EXPECT_LT(w.readable, 40) << r.output;
    EXPECT_EQ(w.unreadable, 0);
    EXPECT_NE(r.output.find("clip.avi"), std::string::npos) << "the end names the file\n" << r.output;
}
