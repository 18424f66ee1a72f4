// arcomp run as a kiosk runs it, under a private Xvfb; and SIGTERM during a
// replay that records a video, which must leave a playable file.

#include "../support/TempDir.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include "tests/support/Shell.hpp"
#include <array>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <set>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

using arcomp::test::TempDir;
namespace fs = std::filesystem;

namespace {

const fs::path kDemo = fs::path(ARCOMP_SOURCE_DIR) / "configs/demo-replay.yaml";

}  // namespace

TEST(RunCommand, showsTheCompositedStationInAWindowAndExitsAfterItsFrames) {
    if (arcomp::test::shell("command -v Xvfb").code != 0) GTEST_SKIP() << "Xvfb not installed";
    TempDir dir;
    const fs::path shot = dir.path() / "shot.png";
    // with-xvfb takes a free display once the server is ready, so concurrent
    // window tests do not race for one.
    const auto [code, out] = arcomp::test::shell(
        std::string(ARCOMP_SOURCE_DIR) + "/scripts/with-xvfb " + std::string(ARCOMP_BINARY) + " run " + kDemo.string() +
        " --windowed --size 640x480 --frames 30 --overlay --screenshot " + shot.string());
    ASSERT_EQ(code, 0) << out;
    const cv::Mat image = cv::imread(shot.string());
    ASSERT_FALSE(image.empty()) << out;
    EXPECT_EQ(image.size(), cv::Size(640, 480));
    // Not blank: a composited frame has many distinct colours.
    std::set<int> colours;
    for (auto it = image.begin<cv::Vec3b>(); it != image.end<cv::Vec3b>(); ++it)
        colours.insert((*it)[0] << 16 | (*it)[1] << 8 | (*it)[2]);
    EXPECT_GT(colours.size(), 500u);
}

// OpenCV's writer (.avi) and GStreamer's H.264 in MP4 and Matroska alike.
class SigtermDuringReplay : public ::testing::TestWithParam<const char*> {};

TEST_P(SigtermDuringReplay, leavesAPlayableVideoToTheLastFrame) {
    TempDir dir;
    const fs::path video = dir.path() / (std::string("out") + GetParam());
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        // The pattern replay runs for 2000 frames unless stopped.
        const std::string config =
            dir.write("station.yaml", "scene:\n  objects:\n    - shape: box\n      position: [0, 0, -4]\n"
                                      "camera: {eye: [0, 0, 0], target: [0, 0, -1]}\n"
                                      "video: {source: pattern, size: [320, 240]}\n")
                .string();
        execl(ARCOMP_BINARY, ARCOMP_BINARY, "replay", config.c_str(), "--out", (dir.path() / "frames").c_str(),
              "--frames", "2000", "--video-out", video.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    // Stop it once a few frames are written.
    auto frames = [&] {
        std::size_t n = 0;
        if (fs::exists(dir.path() / "frames"))
            for (const auto& e : fs::directory_iterator(dir.path() / "frames")) n += e.path().extension() == ".png";
        return n;
    };
    for (int i = 0; i < 600 && frames() < 10; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    ASSERT_GE(frames(), 10u) << "the replay did not start";
    kill(child, SIGTERM);
    int status = 0;
    waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status)) << "killed by the signal instead of stopping";
    EXPECT_EQ(WEXITSTATUS(status), 0);
    const std::size_t written = frames();
    EXPECT_LT(written, 2000u);

    cv::VideoCapture capture(video.string(), cv::CAP_FFMPEG);
    ASSERT_TRUE(capture.isOpened());
    std::size_t decoded = 0;
    cv::Mat frame;
    while (capture.read(frame)) ++decoded;
    EXPECT_EQ(decoded, written) << "every composited frame is in the video, the last one too";
}

INSTANTIATE_TEST_SUITE_P(Files, SigtermDuringReplay, ::testing::Values(".avi", ".mp4", ".mkv"),
                         [](const auto& info) { return std::string(info.param + 1); });
