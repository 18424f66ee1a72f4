// `arcomp-bench cull` end to end, short: both layouts report every frame of
// both sides, and where OpenSceneGraph is built its counts agree with ours
// frame by frame while the two sides take turns. The speed is the
// benchmark's to judge.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "tests/support/Shell.hpp"

TEST(CullBench, bothSidesSeeTheSameObjectsEveryFrameInBothLayouts) {
    for (const char* layout : {"flat", "tree"}) {
        // 45 frames: two full turns of 20 and a short third one.
        const auto r =
            arcomp::test::benchCommand(std::string("cull --objects 2000 --frames 45 --layout ") + layout, false);
        ASSERT_EQ(r.code, 0) << r.out;
        const YAML::Node json = YAML::Load(arcomp::test::lastLine(r.out));
        EXPECT_EQ(json["frames"].as<int>(), 45);
        EXPECT_GT(json["visible_median"].as<double>(), 0.0) << r.out;
        EXPECT_EQ(json["measured_frames"].as<int>(), 45) << r.out;
        if (!json["osg_ms_per_frame_median"].IsDefined()) {
            EXPECT_TRUE(json["osg"].IsDefined()) << r.out;
            continue;
        }
        EXPECT_TRUE(json["counts_match_osg"].as<bool>()) << layout << ": " << r.out;
        EXPECT_EQ(json["osg_measured_frames"].as<int>(), 45) << r.out;
        EXPECT_EQ(json["frames_with_count_mismatch"].as<int>(), 0) << layout;
        EXPECT_EQ(json["osg_visible_median"].as<double>(), json["visible_median"].as<double>()) << layout;
    }
}
