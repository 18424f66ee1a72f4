// The cost model's calibration file: written and read back, bad files
// reported with their place.
#include "runtime/config/CalibrationFile.hpp"
#include "runtime/config/ConfigError.hpp"

#include "../support/TempDir.hpp"

#include <gtest/gtest.h>

using namespace arcomp;
using arcomp::test::TempDir;

TEST(CalibrationFile, roundTripsEveryCoefficient) {
    TempDir dir;
    CostModel m(3);
    for (std::size_t l = 0; l < 3; ++l)
        for (int s = 0; s < kShadingCount; ++s)
            m.set(l, static_cast<Shading>(s), {1e-6 * double(s + 1), 0.5 * double(3 - l)});
    m.overheadMs = 1.25;
    writeCalibration(dir.path() / "c.yaml", m, {"gl33: test", {1280, 720}});
    CalibrationInfo info;
    const CostModel r = readCalibration(dir.path() / "c.yaml", &info);
    ASSERT_EQ(r.levels(), 3u);
    EXPECT_DOUBLE_EQ(r.overheadMs, 1.25);
    EXPECT_EQ(info.device, "gl33: test");
    EXPECT_EQ(info.viewport, glm::ivec2(1280, 720));
    for (std::size_t l = 0; l < 3; ++l)
        for (int s = 0; s < kShadingCount; ++s) {
            EXPECT_NEAR(r.at(l, static_cast<Shading>(s)).msPerPixel, 1e-6 * double(s + 1), 1e-12);
            EXPECT_NEAR(r.at(l, static_cast<Shading>(s)).ms, 0.5 * double(3 - l), 1e-9);
        }
}

TEST(CalibrationFile, reportsBadEntriesWithTheirPlace) {
    TempDir dir;
    const auto file = dir.write("c.yaml", "overhead_ms: 1\nlevels:\n  - {unlit: [0, 1], flat: [-1, 1], gouraud: 3}\n");
    try {
        readCalibration(file);
        FAIL() << "expected a ConfigError";
    } catch (const ConfigError& e) {
        std::string all;
        for (const ConfigIssue& i : e.issues) all += i.format() + "\n";
        EXPECT_NE(all.find("flat: expected [A ms/pixel, B ms]"), std::string::npos) << all;
        EXPECT_NE(all.find("gouraud: expected [A ms/pixel, B ms]"), std::string::npos) << all;
        EXPECT_NE(all.find("phong: missing"), std::string::npos) << all;
        EXPECT_NE(all.find("c.yaml:3:"), std::string::npos) << all;
    }
}
