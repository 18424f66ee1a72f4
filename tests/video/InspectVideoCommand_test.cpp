// Runs the built `arcomp inspect-video`; skips when the executable has not been built.
#include <gtest/gtest.h>

#include "tests/support/OpencvVideos.hpp"
#include "tests/support/Shell.hpp"
#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

namespace {

arcomp::test::ShellResult inspectVideo(const std::string& args) {
    return arcomp::test::arcompCommand("inspect-video " + args);
}

}  // namespace

TEST(InspectVideoCommand, listsCodecSizeRateAndFrameCountOfAFile) {
    if (!std::filesystem::exists(ARCOMP_BINARY)) GTEST_SKIP() << "arcomp not built";
    if (!std::filesystem::exists(arcomp::test::kVtest)) GTEST_SKIP() << arcomp::test::kVtest << " absent";
    const auto r = inspectVideo(arcomp::test::kVtest);
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("size 768x576"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("fps 10.000"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("frames 795"), std::string::npos) << r.out;
}

TEST(InspectVideoCommand, missingFileOrDeviceIsBadInput) {
    if (!std::filesystem::exists(ARCOMP_BINARY)) GTEST_SKIP() << "arcomp not built";
    const auto file = inspectVideo("/nonexistent/clip.mp4");
    EXPECT_EQ(file.code, 2) << file.out;
    EXPECT_NE(file.out.find("/nonexistent/clip.mp4: file does not exist"), std::string::npos) << file.out;
    const auto dev = inspectVideo("/dev/v4l/by-id/usb-not-plugged-video-index0");
    EXPECT_EQ(dev.code, 2) << dev.out;
    EXPECT_NE(dev.out.find("not present"), std::string::npos) << dev.out;
}
