// The demo's zones against people counted by eye on vtest.avi
// (tests/data/vtest-zones.yaml): over the first 300 frames the station's
// enter events may exceed the count by at most 10 %. It misses some (two
// people walking side by side are one shape to the matte), so it must
// only find at least half of them. The whole file (795 frames) is in the
// issue's closing note, by the same command without --frames.

#include "tests/support/Shell.hpp"
#include "tests/support/TempDir.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

TEST(DemoZones, enterEventsExceedTheCountByEyeByAtMostATenth) {
    const fs::path vtest = "/usr/share/doc/opencv-doc/examples/data/vtest.avi";
    if (!fs::exists(vtest)) GTEST_SKIP() << vtest << " absent (opencv-doc not installed)";
    constexpr int kFrames = 300;
    const YAML::Node counted = YAML::LoadFile(std::string(ARCOMP_SOURCE_DIR) + "/tests/data/vtest-zones.yaml");
    arcomp::test::TempDir dir;
    const auto r =
        arcomp::test::arcompCommand("replay " + std::string(ARCOMP_SOURCE_DIR) + "/configs/demo-replay.yaml --frames " +
                                    std::to_string(kFrames) + " --out " + dir.path().string());
    ASSERT_EQ(r.code, 0) << r.out;
    std::ifstream log(dir.path() / "events.jsonl");
    std::map<std::string, int> entered;
    for (std::string line; std::getline(log, line);)
        for (const char* zone : {"plaza", "walk"})
            if (line.find(std::string(R"("event":"enter","zone":")") + zone + "\"") != std::string::npos)
                ++entered[zone];
    for (const char* zone : {"plaza", "walk"}) {
        int byEye = 0;
        for (const YAML::Node& frame : counted["zones"][zone]["entries"]) byEye += frame.as<int>() < kFrames;
        ASSERT_GT(byEye, 3) << zone;
        EXPECT_LE(entered[zone], static_cast<int>(std::floor(1.1 * byEye))) << zone << ": counted by eye " << byEye;
        EXPECT_GE(2 * entered[zone], byEye) << zone << ": counted by eye " << byEye;
    }
}
