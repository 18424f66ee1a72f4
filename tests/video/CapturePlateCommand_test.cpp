// Runs the built `arcomp capture-plate`; skips when the executable has not been built.
#include "tests/support/Shell.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <fstream>

namespace {

namespace fs = std::filesystem;

fs::path writeConfig(const std::string& name, const std::string& video) {
    const fs::path file = fs::path(::testing::TempDir()) / name;
    std::ofstream(file) << "scene:\n  objects:\n    - shape: box\n" << video;
    return file;
}

} // namespace

TEST(CapturePlateCommand, writesTheMeanOfTheSourcesFrames) {
    if (!fs::exists(ARCOMP_BINARY)) GTEST_SKIP() << "arcomp not built";
    const fs::path config = writeConfig("plate-pattern.yaml", "video:\n  source: pattern\n  size: [64, 48]\n  fps: 100\n");
    const fs::path plate = fs::path(::testing::TempDir()) / "plates" / "plate.png";
    fs::remove(plate);
    const auto r = arcomp::test::arcompCommand("capture-plate " + config.string() + " --out " + plate.string() +
                                               " --frames 5 --settle 2");
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("mean of 5 frames"), std::string::npos) << r.out;
    const cv::Mat image = cv::imread(plate.string());
    ASSERT_FALSE(image.empty());
    EXPECT_EQ(image.size(), cv::Size(64, 48));
}

TEST(CapturePlateCommand, aConfigWithoutVideoOrAMissingFileIsBadInput) {
    if (!fs::exists(ARCOMP_BINARY)) GTEST_SKIP() << "arcomp not built";
    const fs::path plate = fs::path(::testing::TempDir()) / "never.png";
    const auto noVideo = arcomp::test::arcompCommand("capture-plate " + writeConfig("plate-none.yaml", "").string() +
                                                     " --out " + plate.string());
    EXPECT_EQ(noVideo.code, 2) << noVideo.out;
    EXPECT_NE(noVideo.out.find("no `video` section"), std::string::npos) << noVideo.out;

    const fs::path config = writeConfig("plate-missing.yaml", "video:\n  source: file\n  path: /nonexistent/empty-place.avi\n");
    const auto missing = arcomp::test::arcompCommand("capture-plate " + config.string() + " --out " + plate.string());
    EXPECT_EQ(missing.code, 2) << missing.out;
    EXPECT_NE(missing.out.find("got 0 of 30 frames"), std::string::npos) << missing.out;
    EXPECT_FALSE(fs::exists(plate));
}
