// `arcomp bake lod` end to end: the issue's acceptance command on the bunny.
#include "graph/io/LodFile.hpp"

#include "../support/QuadGltf.hpp"
#include "../support/TempDir.hpp"

#include <gtest/gtest.h>

#include "tests/support/Shell.hpp"
#include <cstdio>
#include <filesystem>
#include <string>

namespace {

using arcomp::test::lastLine;

// Only stdout: the JSON or summary the command prints.
arcomp::test::ShellResult arcompRun(const std::string& args) { return arcomp::test::arcompCommand(args, false); }

}  // namespace

TEST(BakeLod, bunnyLevelsWithinTenPercentAndFileReadsBack) {
    const std::string bunny = std::string(ARCOMP_SHARED_DATA) + "/meshes/bunny.obj";
    if (!std::filesystem::exists(bunny)) GTEST_SKIP() << "no shared data";
    const std::filesystem::path out = std::filesystem::path(ARCOMP_TEST_OUTPUT) / "bunny.lod";
    std::filesystem::create_directories(out.parent_path());
    const auto r = arcompRun("bake lod " + bunny + " --ratios 1,0.25,0.05 --out " + out.string());
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("\"all_within_10_percent\":true"), std::string::npos) << r.out;
    const std::vector<arcomp::LodLevel> levels = arcomp::readLodFile(out);
    ASSERT_EQ(levels.size(), 3u);
    EXPECT_NEAR(levels[2].geometry.triangleCount(), 27864 * 0.05, 27864 * 0.05 * 0.1);
}

TEST(BakeLod, badRatiosAreBadInput) {
    EXPECT_EQ(arcompRun("bake lod /nonexistent.obj --ratios 1,2").code, 2);
    EXPECT_EQ(arcompRun("bake lod /nonexistent.obj --ratios 1,0.5").code, 2);
}

TEST(BakeLod, mergedTangentsKeepTheirFrameUnderAMirroringNode) {
    // The quad twice, once mirrored in x; its normal map has tangents
    // generated: (1, 0, 0, +1) on the quad as written.
    arcomp::test::QuadGltf q;
    q.materials = R"([{"normalTexture": {"index": 0}}])";
    q.nodes = R"([{"mesh": 0}, {"mesh": 0, "scale": [-1, 1, 1]}])";
    q.sceneNodes = "[0, 1]";
    arcomp::test::TempDir dir;
    const auto out = dir.path() / "quads.lod";
    const auto r =
        arcompRun("bake lod " + dir.write("quads.gltf", q.json()).string() + " --ratios 1 --out " + out.string());
    ASSERT_EQ(r.code, 0) << r.out;
    const arcomp::Geometry g = arcomp::readLodFile(out).at(0).geometry;
    ASSERT_EQ(g.tangents.size(), 8u);
    EXPECT_TRUE(g.tangentsGenerated);
    // The bitangent cross(n, t) * w must still be +y, up the image, on both.
    for (std::size_t v = 0; v < 8; ++v) {
        const glm::vec3 bitangent = glm::cross(g.normals[v], glm::vec3(g.tangents[v])) * g.tangents[v].w;
        EXPECT_NEAR(bitangent.y, 1.0f, 1e-5f) << v;
        EXPECT_NEAR(g.tangents[v].x, v < 4 ? 1.0f : -1.0f, 1e-5f) << v;
    }
    EXPECT_EQ(g.tangents[4].w, -1.0f);
}
