// Runs the built `arcomp capture-plate`; skips when the executable has not been built.
#include "tests/support/Shell.hpp"
#include "tests/support/TempDir.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <fstream>

namespace {

namespace fs = std::filesystem;

fs::path writeConfig(const fs::path& file, const std::string& video) {
    std::ofstream(file) << "scene:\n  objects:\n    - shape: box\n" << video;
    return file;
}

}  // namespace

TEST(CapturePlateCommand, writesTheMeanOfTheSourcesFrames) {
    if (!fs::exists(ARCOMP_BINARY)) GTEST_SKIP() << "arcomp not built";
    const arcomp::test::TempDir tmp;
    const fs::path config =
        writeConfig(tmp.path() / "plate-pattern.yaml", "video:\n  source: pattern\n  size: [64, 48]\n  fps: 100\n");
    const fs::path plate = tmp.path() / "plates" / "plate.png";
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
    const arcomp::test::TempDir tmp;
    const fs::path plate = tmp.path() / "never.png";
    const fs::path noVideoConfig = writeConfig(tmp.path() / "plate-none.yaml", "");
    const auto noVideo =
        arcomp::test::arcompCommand("capture-plate " + noVideoConfig.string() + " --out " + plate.string());
    EXPECT_EQ(noVideo.code, 2) << noVideo.out;
    EXPECT_NE(noVideo.out.find("no `video` section"), std::string::npos) << noVideo.out;

    const fs::path config = writeConfig(tmp.path() / "plate-missing.yaml",
                                        "video:\n  source: file\n  path: /nonexistent/empty-place.avi\n");
    const auto missing = arcomp::test::arcompCommand("capture-plate " + config.string() + " --out " + plate.string());
    EXPECT_EQ(missing.code, 2) << missing.out;
    EXPECT_NE(missing.out.find("got 0 of 30 frames"), std::string::npos) << missing.out;
    EXPECT_FALSE(fs::exists(plate));
}
