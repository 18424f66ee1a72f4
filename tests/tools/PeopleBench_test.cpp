// `arcomp-bench people` end to end on a short run of the `ar`
// installation: the line has the fields for both mattes, every
// datagram the stations sent arrived, and the walkers are found where they
// walk (position is a measurement, not a speed: it may be held here), and
// the zone events come within a few frames of the true crossings.

#include "tests/support/Shell.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

TEST(PeopleBench, shortRunFindsTheWalkersAndSendsEveryFrame) {
    const std::filesystem::path out = std::filesystem::path(ARCOMP_TEST_OUTPUT) / "bench-people-short";
    std::filesystem::remove_all(out);
    const auto r = arcomp::test::benchCommand("people --frames 60 --out " + out.string(), false);
    ASSERT_EQ(r.code, 0) << r.out;
    const nlohmann::json line = nlohmann::json::parse(arcomp::test::lastLine(r.out));
    EXPECT_EQ(line["bench"], "people");
    for (const char* matte : {"true_masks", "own_matte"}) {
        const nlohmann::json& m = line[matte];
        for (const char* key :
             {"position_err_m_median", "position_err_m_p95", "bias_along_view_m", "bias_along_view_m_uncorrected",
              "velocity_err_mps_median", "id_switches_per_walker_min", "losses_per_walker_min", "people_ms_median",
              "capture_to_sent_ms_median"})
            EXPECT_TRUE(m.contains(key) && m[key].is_number()) << matte << " " << key << "\n" << r.out;
        EXPECT_EQ(m["datagrams_sent"], 2 * 60) << matte << ": OSC and TUIO, each frame";
        EXPECT_GT(m["matched_pct"].get<double>(), 90.0) << matte;
        EXPECT_LE(m["position_err_m_median"].get<double>(), 0.15) << matte;
    }
    EXPECT_TRUE(std::filesystem::exists(out / "camera.yaml")) << "the station calibrated the camera itself";
    // In 60 frames two walkers cross into a zone each (frames 24 and 52 of the true paths).
    const nlohmann::json& zones = line["zones"];
    EXPECT_GE(zones["true_events_in_full_view"].get<int>(), 1) << r.out;
    EXPECT_GE(zones["station_events"].get<int>(), 1) << r.out;
    EXPECT_EQ(zones["missed"], 0) << r.out;
    EXPECT_EQ(zones["spurious"], 0) << r.out;
    EXPECT_LE(zones["timing_err_frames_median"].get<double>(), 3.0) << r.out;
    EXPECT_GE(zones["triggers_fired"].get<int>(), 1) << r.out;
    EXPECT_TRUE(zones["zones_and_triggers_ms"].is_number()) << r.out;
}
