// `arcomp-bench ar` end to end, short: the last line carries the issue's
// fields, the calibration commands it drives give back the camera, and the
// single person plane is already worse than per-person depth. The layering
// and cost targets over 300 frames are the benchmark's to judge.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "tests/support/Shell.hpp"

#include <filesystem>

TEST(ArBench, reportsLayeringCalibrationAndCostAndWritesTheStrip) {
    const std::filesystem::path out = std::filesystem::path(ARCOMP_TEST_OUTPUT) / "bench-ar-short";
    const auto r = arcomp::test::benchCommand("ar --frames 130 --out " + out.string(), false);
    ASSERT_EQ(r.code, 0) << r.out;
    const YAML::Node json = YAML::Load(arcomp::test::lastLine(r.out));
    for (const char* key : {"frames", "wrong_layering_pct", "wrong_layering_pct_own_matte",
                            "wrong_layering_pct_single_plane", "calibration", "added_ms_768x576"})
        EXPECT_TRUE(json[key].IsDefined()) << key << " is missing from " << r.out;
    for (const char* key : {"focal_err_pct", "principal_err_px", "rms_px", "height_err_pct", "tilt_err_deg"})
        EXPECT_TRUE(json["calibration"][key].IsDefined()) << key << " is missing from " << r.out;
    EXPECT_EQ(json["frames"].as<int>(), 130);  // the walkers reach the box after about 100
    EXPECT_LT(json["calibration"]["focal_err_pct"].as<double>(), 1.0) << r.out;
    EXPECT_LT(json["calibration"]["height_err_pct"].as<double>(), 2.0) << r.out;
    EXPECT_LT(json["wrong_layering_pct"].as<double>(), json["wrong_layering_pct_single_plane"].as<double>()) << r.out;
    EXPECT_TRUE(std::filesystem::exists(out / "strip.png"));
    EXPECT_TRUE(std::filesystem::exists(out / "camera.yaml"));
}
