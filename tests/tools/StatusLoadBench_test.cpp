// `arcomp-bench status-load` end to end, small: the last line carries the
// issue's fields, every scrape was answered while the hostile clients were
// connected, and those clients really did press on the server's bounds.
// The latency and frame-time targets are the benchmark's to judge.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "tests/support/Shell.hpp"

TEST(StatusLoadBench, scrapesAreAnsweredWhileIdleSlowAndGarbageClientsFillTheTable) {
    // 200 idle clients from 64 addresses: past the 128-connection table.
    const auto r = arcomp::test::benchCommand("status-load --seconds 2 --idle 200 --slow 6 --garbage 6 --fps 0", false);
    ASSERT_EQ(r.code, 0) << r.out;
    const YAML::Node json = YAML::Load(arcomp::test::lastLine(r.out));
    for (const char* key : {"scrape_p99_ms", "scrape_max_ms", "scrape_failures", "idle_connections", "slow_clients",
                            "garbage_clients", "frame_time_change_pct"})
        EXPECT_TRUE(json[key].IsDefined()) << key << " is missing from " << r.out;
    EXPECT_EQ(json["idle_connections"].as<int>(), 200);
    EXPECT_GE(json["scrapes"].as<int>(), 10);
    EXPECT_EQ(json["scrape_failures"].as<int>(), 0) << r.out;
    EXPECT_EQ(json["quiet"]["scrape_failures"].as<int>(), 0) << r.out;
    EXPECT_GE(json["hostile_clients"]["most_open_at_once"].as<int>(), 200 + 6 + 6) << r.out;
    EXPECT_GT(json["server"]["evicted"].as<int>(), 0) << r.out;      // the table was full
    EXPECT_GT(json["server"]["refused_4xx"].as<int>(), 0) << r.out;  // garbage got 400
}
