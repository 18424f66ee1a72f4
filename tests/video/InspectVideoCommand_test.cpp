// Runs the built `arcomp inspect-video`; skips when the executable has not been built.
#include <gtest/gtest.h>

#include "tests/support/Shell.hpp"
#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

namespace {

arcomp::test::ShellResult run(const std::string& args) { return arcomp::test::arcompCommand("inspect-video " + args); }

const std::string kVtest = "/usr/share/doc/opencv-doc/examples/data/vtest.avi";

}  // namespace

TEST(InspectVideoCommand, listsCodecSizeRateAndFrameCountOfAFile) {
    if (!std::filesystem::exists(ARCOMP_BINARY)) GTEST_SKIP() << "arcomp not built";
    if (!std::filesystem::exists(kVtest)) GTEST_SKIP() << kVtest << " absent";
    const auto r = run(kVtest);
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("size 768x576"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("fps 10.000"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("frames 795"), std::string::npos) << r.out;
}

TEST(InspectVideoCommand, missingFileOrDeviceIsBadInput) {
    if (!std::filesystem::exists(ARCOMP_BINARY)) GTEST_SKIP() << "arcomp not built";
    const auto file = run("/nonexistent/clip.mp4");
    EXPECT_EQ(file.code, 2) << file.out;
    EXPECT_NE(file.out.find("/nonexistent/clip.mp4: file does not exist"), std::string::npos) << file.out;
    const auto dev = run("/dev/v4l/by-id/usb-not-plugged-video-index0");
    EXPECT_EQ(dev.code, 2) << dev.out;
    EXPECT_NE(dev.out.find("not present"), std::string::npos) << dev.out;
}
