// `arcomp-bench gltf-reference` without a browser: CI has none, so the bench
// must say it skipped the reference, and why, and exit 0, having still
// written the models. (Runs with a browser are the benchmark itself.)
#include "../support/Shell.hpp"
#include "../support/TempDir.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>

namespace arcomp {
namespace {

using test::benchCommand;
using test::lastLine;
using test::TempDir;

TEST(GltfReferenceBench, withoutChromiumSkipsAndSucceeds) {
    TempDir dir;
    const auto r =
        benchCommand("gltf-reference --out " + dir.path().string() + " --models emissive,skinned-bend --chromium " +
                         (dir.path() / "no-chromium").string(),
                     false);
    ASSERT_EQ(r.code, 0) << r.out;
    const YAML::Node line = YAML::Load(lastLine(r.out));
    EXPECT_EQ(line["bench"].as<std::string>(), "gltf-reference");
    EXPECT_TRUE(line["skipped"].as<bool>());
    EXPECT_NE(line["reason"].as<std::string>().find("no-chromium"), std::string::npos) << line["reason"];
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "models/emissive.gltf"));
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "models/skinned-bend.gltf"));
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "models/neutral.hdr"));
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "models/vertex-colors.gltf")) << "only the models asked for";
}

TEST(GltfReferenceBench, unknownModelIsBadInput) {
    TempDir dir;
    const auto r = benchCommand("gltf-reference --out " + dir.path().string() + " --models teapot");
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_NE(r.out.find("teapot"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("vertex-colors"), std::string::npos) << "the error lists the models there are: " << r.out;
}

}  // namespace
}  // namespace arcomp
