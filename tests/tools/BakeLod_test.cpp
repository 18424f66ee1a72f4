// `arcomp bake lod` end to end: the acceptance command on the bunny.
#include "graph/io/LodFile.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include "tests/support/Shell.hpp"

namespace {

using arcomp::test::lastLine;

// Only stdout: the JSON or summary the command prints.
arcomp::test::ShellResult run(const std::string& args) { return arcomp::test::arcompCommand(args, false); }



} // namespace

TEST(BakeLod, bunnyLevelsWithinTenPercentAndFileReadsBack) {
    const std::string bunny = std::string(ARCOMP_SHARED_DATA) + "/meshes/bunny.obj";
    if (!std::filesystem::exists(bunny)) GTEST_SKIP() << "no shared data";
    const std::filesystem::path out = std::filesystem::path(ARCOMP_TEST_OUTPUT) / "bunny.lod";
    std::filesystem::create_directories(out.parent_path());
    const auto r = run("bake lod " + bunny + " --ratios 1,0.25,0.05 --out " + out.string());
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("\"all_within_10_percent\":true"), std::string::npos) << r.out;
    const std::vector<arcomp::LodLevel> levels = arcomp::readLodFile(out);
    ASSERT_EQ(levels.size(), 3u);
    EXPECT_NEAR(levels[2].geometry.triangleCount(), 27864 * 0.05, 27864 * 0.05 * 0.1);
}

TEST(BakeLod, badRatiosAreBadInput) {
    EXPECT_EQ(run("bake lod /nonexistent.obj --ratios 1,2").code, 2);
    EXPECT_EQ(run("bake lod /nonexistent.obj --ratios 1,0.5").code, 2);
}
