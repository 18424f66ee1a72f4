// Runs the built `arcomp inspect-video`; skips when the executable has not been built.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

namespace {

struct CommandRun {
    int code = -1;
    std::string out;
};

CommandRun run(const std::string& args) {
    CommandRun r;
    FILE* p = ::popen((std::string(ARCOMP_BINARY) + " inspect-video " + args + " 2>&1").c_str(), "r");
    std::array<char, 512> buf{};
    while (std::fgets(buf.data(), buf.size(), p)) r.out += buf.data();
    const int status = ::pclose(p);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

const std::string kVtest = "/usr/share/doc/opencv-doc/examples/data/vtest.avi";

} // namespace

TEST(InspectVideoCommand, listsCodecSizeRateAndFrameCountOfAFile) {
    if (!std::filesystem::exists(ARCOMP_BINARY)) GTEST_SKIP() << "arcomp not built";
    if (!std::filesystem::exists(kVtest)) GTEST_SKIP() << kVtest << " absent";
    const CommandRun r = run(kVtest);
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("size 768x576"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("fps 10.000"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("frames 795"), std::string::npos) << r.out;
}

TEST(InspectVideoCommand, missingFileOrDeviceIsBadInput) {
    if (!std::filesystem::exists(ARCOMP_BINARY)) GTEST_SKIP() << "arcomp not built";
    const CommandRun file = run("/nonexistent/clip.mp4");
    EXPECT_EQ(file.code, 2) << file.out;
    EXPECT_NE(file.out.find("/nonexistent/clip.mp4: file does not exist"), std::string::npos) << file.out;
    const CommandRun dev = run("/dev/v4l/by-id/usb-not-plugged-video-index0");
    EXPECT_EQ(dev.code, 2) << dev.out;
    EXPECT_NE(dev.out.find("not present"), std::string::npos) << dev.out;
}
