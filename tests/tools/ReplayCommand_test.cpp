// arcomp replay as scripts use it: frame counts, fallbacks, the video
// output finished properly, exit codes for bad input.

#include "video/sources/FileSource.hpp"
#include "video/sources/TestPatternSource.hpp"
#include "video/sources/VideoFileWriter.hpp"

#include "../support/TempDir.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "tests/support/BoxStation.hpp"
#include "tests/support/Shell.hpp"
#include "tests/support/VideoPsnr.hpp"
#include "tools/bench/scenes/NumberedFrames.hpp"
#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <sys/wait.h>

using arcomp::test::TempDir;
namespace fs = std::filesystem;

namespace {

arcomp::test::ShellResult replay(const std::string& args) { return arcomp::test::arcompCommand("replay " + args); }

const char* const kScene = arcomp::test::kBoxStation;

std::size_t pngsIn(const fs::path& dir) {
    std::size_t n = 0;
    for (const auto& e : fs::directory_iterator(dir)) n += e.path().extension() == ".png";
    return n;
}

}  // namespace

TEST(ReplayCommand, wholeFileIsReplayedFrameForFrame) {
    TempDir dir;
    const fs::path clip = dir.path() / "clip.avi";
    {
        arcomp::TestPatternSource pattern({.width = 160, .height = 120, .paced = false});
        arcomp::VideoFileWriter w(clip.string(), "MJPG", 10.0, {160, 120});
        for (int i = 0; i < 7; ++i) w.write(pattern.render(static_cast<std::uint64_t>(i)));
    }
    const auto cfg = dir.write("s.yaml", std::string(kScene) + "matte:\n  kind: background\n");
    const auto r = replay(cfg.string() + " --video " + clip.string() + " --out " + (dir.path() / "out").string());
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(pngsIn(dir.path() / "out"), 7u);
    EXPECT_TRUE(fs::exists(dir.path() / "out/frame-000006.png"));
}

TEST(ReplayCommand, missingFileWithAFallbackWarnsAndReplaysThePattern) {
    TempDir dir;
    const auto cfg = dir.write("s.yaml", std::string(kScene) +
                                             "video:\n  path: nowhere.avi\n  fallback: pattern\n  size: [160, 120]\n");
    const auto r = replay(cfg.string() + " --frames 3 --out " + (dir.path() / "out").string());
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("warning"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("nowhere.avi"), std::string::npos) << r.out;
    EXPECT_EQ(pngsIn(dir.path() / "out"), 3u);
}

TEST(ReplayCommand, missingFileWithoutFallbackIsBadInput) {
    TempDir dir;
    const auto cfg = dir.write("s.yaml", std::string(kScene) + "video:\n  path: nowhere.avi\n");
    const auto r = replay(cfg.string() + " --out " + (dir.path() / "out").string());
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_NE(r.out.find("nowhere.avi"), std::string::npos) << r.out;
}

TEST(ReplayCommand, noVideoAnywhereIsBadInput) {
    TempDir dir;
    const auto cfg = dir.write("s.yaml", kScene);
    const auto r = replay(cfg.string() + " --out " + (dir.path() / "out").string());
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_NE(r.out.find("no `video` section"), std::string::npos) << r.out;
}

TEST(ReplayCommand, videoOutputIsAFinishedPlayableFile) {
    TempDir dir;
    const auto cfg = dir.write("s.yaml", std::string(kScene) + "video:\n  source: pattern\n  size: [160, 120]\n");
    const fs::path movie = dir.path() / "movie.avi";
    const auto r =
        replay(cfg.string() + " --frames 6 --out " + (dir.path() / "out").string() + " --video-out " + movie.string());
    ASSERT_EQ(r.code, 0) << r.out;
    arcomp::FileSource file({.path = movie.string()});
    EXPECT_EQ(file.info().width, 160);
    int frames = 0;
    while (file.next()) ++frames;
    EXPECT_EQ(frames, 6);
}

// Issue #60: an .mp4 is H.264 that browsers play; a replay keeps every
// frame in it, in order, as the composited PNGs show them.
TEST(ReplayCommand, mp4OutputIsH264OfEveryCompositedFrameInOrder) {
    TempDir dir;
    const fs::path input = arcomp::writeNumberedVideo(dir.path() / "numbered.avi", 30, {320, 240});
    const auto cfg = dir.write("s.yaml", std::string(kScene) + "video:\n  path: " + input.string() + "\n");
    const fs::path movie = dir.path() / "movie.mp4";
    const auto r = replay(cfg.string() + " --out " + (dir.path() / "out").string() + " --video-out " + movie.string());
    ASSERT_EQ(r.code, 0) << r.out;
    cv::VideoCapture in(movie.string(), cv::CAP_FFMPEG);
    ASSERT_TRUE(in.isOpened());
    EXPECT_EQ(static_cast<int>(in.get(cv::CAP_PROP_FOURCC)), cv::VideoWriter::fourcc('a', 'v', 'c', '1'))
        << "H.264 as MP4 names it";
    cv::Mat decoded;
    int frames = 0;
    double worst = 1e9;
    while (in.read(decoded)) {
        ASSERT_EQ(arcomp::frameNumberOf(decoded), frames) << "frame " << frames << " out of order";
        char name[32];
        std::snprintf(name, sizeof name, "frame-%06d.png", frames);
        const cv::Mat composited = cv::imread((dir.path() / "out" / name).string(), cv::IMREAD_COLOR);
        ASSERT_FALSE(composited.empty()) << name;
        worst = std::min(worst, arcomp::test::videoPsnr(decoded, composited));
        ++frames;
    }
    EXPECT_EQ(frames, 30);
    EXPECT_GE(worst, 35.0) << "dB, the worst frame at the default bitrate";
}

TEST(ReplayCommand, matteIsWrittenForInspectionWhenAsked) {
    TempDir dir;
    const auto cfg =
        dir.write("s.yaml", std::string(kScene) + "video:\n  source: pattern\n  size: [160, 120]\n"
                                                  "matte:\n  kind: background\n  background:\n    method: clean_plate\n"
                                                  "output:\n  matte_dir: mattes\n");
    const auto r = replay(cfg.string() + " --frames 4 --out " + (dir.path() / "out").string());
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(pngsIn(dir.path() / "mattes"), 4u);
    // The pattern's moving shapes differ from the first frame: some alpha.
    const cv::Mat alpha = cv::imread((dir.path() / "mattes/matte-000003.png").string(), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(alpha.type(), CV_8UC1);
    EXPECT_GT(cv::countNonZero(alpha), 0);
}

// Issue #12: the demo composited on OpenGL ES 3.0 matches desktop GL 3.3.
TEST(ReplayCommand, demoOnEs3MatchesGl33) {
    const fs::path vtest = "/usr/share/doc/opencv-doc/examples/data/vtest.avi";
    if (!fs::exists(vtest)) GTEST_SKIP() << vtest << " absent (opencv-doc not installed)";
    TempDir dir;
    const std::string demo = (fs::path(ARCOMP_SOURCE_DIR) / "configs/demo-replay.yaml").string();
    for (const char* api : {"gl33", "es3"}) {
        const auto r = replay(demo + " --gl " + api + " --frames 8 --out " + (dir.path() / api).string());
        ASSERT_EQ(r.code, 0) << r.out;
        EXPECT_NE(r.out.find(std::string(", ") + api + ", "), std::string::npos)
            << "ran on the API asked for: " << r.out;
    }
    for (int i = 0; i < 8; ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "frame-%06d.png", i);
        const cv::Mat gl = cv::imread((dir.path() / "gl33" / name).string(), cv::IMREAD_UNCHANGED);
        const cv::Mat es = cv::imread((dir.path() / "es3" / name).string(), cv::IMREAD_UNCHANGED);
        ASSERT_FALSE(gl.empty());
        ASSERT_EQ(gl.size(), es.size());
        cv::Mat diff;
        cv::absdiff(gl, es, diff);
        double worst = 0.0;
        cv::minMaxLoc(diff.reshape(1), nullptr, &worst);
        EXPECT_LE(worst, 2.0) << name << ": the two APIs differ by more than 2 levels somewhere";
    }
}

// The demo reacts to its walkers: the plaza's first visitor (frame 11 of
// vtest.avi) shows the sign over the kiosk until the plaza empties (frame
// 44), the walk past the beacon plays it and the beacon pauses when it
// empties, each firing in out/events.jsonl.
TEST(ReplayCommand, theDemosSignShowsWhileThePlazaIsOccupiedAndItsBeaconPlays) {
    const fs::path vtest = "/usr/share/doc/opencv-doc/examples/data/vtest.avi";
    if (!fs::exists(vtest)) GTEST_SKIP() << vtest << " absent (opencv-doc not installed)";
    TempDir dir;
    const std::string demo = (fs::path(ARCOMP_SOURCE_DIR) / "configs/demo-replay.yaml").string();
    const auto r = replay(demo + " --frames 50 --out " + dir.path().string());
    ASSERT_EQ(r.code, 0) << r.out;
    std::ifstream in(dir.path() / "events.jsonl");
    std::vector<std::pair<int, std::string>> firings;  // frame, "welcome fired", ...
    for (std::string line; std::getline(in, line);) {
        const auto trigger = line.find(R"("trigger":")");
        if (trigger == std::string::npos) continue;
        const std::string name = line.substr(trigger + 11, line.find('"', trigger + 11) - trigger - 11);
        const std::string state = line.find(R"("state":"fired")") != std::string::npos ? "fired" : "ended";
        firings.emplace_back(std::stoi(line.substr(9)), name + " " + state);
    }
    const auto at = [&](const std::string& what) {
        const auto f = std::find_if(firings.begin(), firings.end(), [&](const auto& e) { return e.second == what; });
        return f == firings.end() ? -1 : f->first;
    };
    const int on = at("welcome fired"), off = at("welcome ended");
    ASSERT_GT(on, 0) << "someone crosses the plaza in the first 50 frames";
    ASSERT_GT(off, on);
    EXPECT_GE(at("beacon fired"), 0);
    EXPECT_GT(at("beacon ended"), at("beacon fired"));
    // The sign's middle, over the kiosk: green while shown, the square's grey otherwise.
    const auto signShown = [&](int frame) {
        char name[32];
        std::snprintf(name, sizeof name, "frame-%06d.png", frame);
        const cv::Mat image = cv::imread((dir.path() / name).string());
        EXPECT_FALSE(image.empty()) << name;
        if (image.empty()) return false;
        const cv::Vec3b c = image.at<cv::Vec3b>(160, 195);  // BGR
        return c[1] > c[2] + 60 && c[1] > c[0] + 20;
    };
    EXPECT_FALSE(signShown(on - 1));
    EXPECT_TRUE(signShown(on));
    EXPECT_TRUE(signShown(off - 1));
    EXPECT_FALSE(signShown(off));
}
