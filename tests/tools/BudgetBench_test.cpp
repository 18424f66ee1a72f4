// `arcomp-bench budget` end to end on a tiny flight: the JSON line has the
// issue's fields for both runs and the CSV and plots are written. No figure
// is checked against its target here (speed belongs in the benchmark).
#include <gtest/gtest.h>

#include "tests/support/Shell.hpp"
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

using arcomp::test::lastLine;

// Only stdout: the JSON or summary the command prints.
arcomp::test::ShellResult budgetBench(const std::string& args) { return arcomp::test::benchCommand(args, false); }

// The text of `key`'s object, `"key":{...}` without nested objects.
std::string object(const std::string& json, const std::string& key) {
    const std::size_t at = json.find("\"" + key + "\":{");
    if (at == std::string::npos) return {};
    const std::size_t open = json.find('{', at);
    return json.substr(open, json.find('}', open) - open + 1);
}

// The number after `"key":` in json.
double number(const std::string& json, const std::string& key) {
    const std::size_t at = json.find("\"" + key + "\":");
    if (at == std::string::npos) return std::nan("");
    return std::stod(json.substr(at + key.size() + 3));
}

std::size_t lines(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::size_t n = 0;
    for (std::string line; std::getline(in, line);) ++n;
    return n;
}

}  // namespace

TEST(BudgetBench, tinyFlightWritesJsonWithTheIssuesFieldsAndCsvAndPlots) {
    const std::filesystem::path out = std::filesystem::path(ARCOMP_TEST_OUTPUT) / "bench-budget-tiny";
    std::filesystem::remove_all(out);
    const auto r = budgetBench("budget --frames 8 --size 160x90 --mountains 6 --scene-frames 4 --target-ms 5 --out " +
                               out.string());
    ASSERT_EQ(r.code, 0) << r.out;
    const std::string json = lastLine(r.out);
    ASSERT_EQ(json.front(), '{') << json;
    ASSERT_EQ(json.back(), '}') << json;
    EXPECT_NE(json.find("\"bench\":\"budget\""), std::string::npos) << json;
    EXPECT_NE(json.find("\"target_ms\":5.0,"), std::string::npos) << json;
    const std::string unmanaged = object(json, "unmanaged"), managed = object(json, "managed");
    ASSERT_FALSE(unmanaged.empty()) << json;
    ASSERT_FALSE(managed.empty()) << json;
    for (const char* field : {"frame_ms_median", "frame_ms_p95", "frame_ms_max", "frame_ms_stddev"}) {
        EXPECT_NE(unmanaged.find(std::string("\"") + field + "\":"), std::string::npos) << field << " in " << unmanaged;
        EXPECT_NE(managed.find(std::string("\"") + field + "\":"), std::string::npos) << field << " in " << managed;
    }
    for (const char* field : {"p95_abs_dev_from_target_pct", "frames_over_target_by_20pct_pct", "mean_quality",
                              "prediction_error_pct_median"})
        EXPECT_NE(managed.find(std::string("\"") + field + "\":"), std::string::npos) << field << " in " << managed;
    EXPECT_NE(json.find("\"targets_met\":"), std::string::npos) << json;
    // The default rasterizes on the drawing thread, and the JSON says so.
    EXPECT_NE(json.find("\"raster_threads\":0,"), std::string::npos) << json;

    EXPECT_EQ(lines(out / "budget_frames.csv"), 1u + 8u);  // header and one row per frame
    for (const char* png : {"budget_frame_time.png", "budget_prediction.png"}) {
        ASSERT_TRUE(std::filesystem::exists(out / png)) << png;
        EXPECT_GT(std::filesystem::file_size(out / png), 1000u) << png;
    }
    EXPECT_TRUE(std::filesystem::exists(out / "calibration.yaml"));
}

TEST(BudgetBench, badOptionsAreBadInput) {
    EXPECT_EQ(budgetBench("budget --frames 1 --out " + std::string(ARCOMP_TEST_OUTPUT) + "/bench-budget-bad").code, 2);
    EXPECT_EQ(budgetBench("budget --timer sundial --out " + std::string(ARCOMP_TEST_OUTPUT) + "/bench-budget-bad").code,
              2);
    for (const char* threads : {"-2", "65", "two"})
        EXPECT_EQ(budgetBench(std::string("budget --raster-threads ") + threads + " --out " + ARCOMP_TEST_OUTPUT +
                              "/bench-budget-bad")
                      .code,
                  2)
            << threads;
}

TEST(BudgetBench, cpuTimerIsTheOneTheRunUsesAndReports) {
    const std::filesystem::path out = std::filesystem::path(ARCOMP_TEST_OUTPUT) / "bench-budget-cpu";
    const auto r =
        budgetBench("budget --timer cpu --frames 4 --size 160x90 --mountains 4 --scene-frames 2 --target-ms 5 --out " +
                    out.string());
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_NE(lastLine(r.out).find("\"timer\":\"process_cpu_glfinish\""), std::string::npos) << r.out;
}

TEST(BudgetBench, defaultTargetLiesUnderTheUnmanagedRunsFastestFrameAndNotUnderTheFloor) {
    const std::filesystem::path out = std::filesystem::path(ARCOMP_TEST_OUTPUT) / "bench-budget-default-target";
    const auto r = budgetBench("budget --frames 6 --size 160x90 --mountains 6 --scene-frames 4 --out " + out.string());
    ASSERT_EQ(r.code, 0) << r.out;
    const std::string json = lastLine(r.out);
    const double target = number(json, "target_ms"), floor = number(json, "floor_ms_max_estimate");
    const double fastest = number(object(json, "unmanaged"), "frame_ms_min");
    ASSERT_GT(target, 0.0) << json;
    ASSERT_GT(fastest, 0.0) << json;
    // The JSON's numbers read back as the same doubles; the margin is for 0.85 * fastest alone.
    EXPECT_NEAR(target, std::max(0.85 * fastest, floor), 1e-9 * target) << json;
    const bool underFastest = json.find("\"target_rule\":\"under_unmanaged_fastest\"") != std::string::npos;
    const bool atFloor = json.find("\"target_rule\":\"floor\"") != std::string::npos;
    EXPECT_TRUE(underFastest ? 0.85 * fastest >= floor : atFloor && floor > 0.85 * fastest) << json;
}
