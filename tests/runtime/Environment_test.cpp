// The environment behind image-based light: the built-in studio, files in
// and out, the CPU precomputation (irradiance, prefiltered levels, split
// sum) and how a station config names one.

#include "graph/core/BadInput.hpp"
#include "runtime/config/StationConfig.hpp"
#include "runtime/render/Environment.hpp"
#include "runtime/render/ImageBasedLight.hpp"
#include "runtime/station/ImageFile.hpp"
#include "runtime/station/Station.hpp"

#include "../support/TempDir.hpp"

#include <gtest/gtest.h>

#include <functional>

using namespace arcomp;
using arcomp::test::TempDir;

namespace {

Environment uniform(const glm::vec3& radiance) { return {64, 32, std::vector<glm::vec3>(64 * 32, radiance)}; }

std::string messageOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return e.what();
    }
    return {};
}

}  // namespace

TEST(Environment, directionsAndCoordinatesRoundTripInThreeJsLayout) {
    EXPECT_NEAR(equirectangularUv({0, 1, 0}).y, 0.0f, 1e-6f) << "row 0 is up";
    EXPECT_NEAR(equirectangularUv({1, 0, 0}).x, 0.5f, 1e-6f) << "+X in the middle";
    EXPECT_NEAR(equirectangularUv({0, 0, 1}).x, 0.75f, 1e-6f) << "+Z three quarters across";
    const glm::vec3 d = glm::normalize(glm::vec3(0.3f, -0.5f, -0.8f));
    EXPECT_LT(glm::length(equirectangularDirection(equirectangularUv(d)) - d), 1e-5f);
}

TEST(Environment, neutralStudioIsGreyBrightAboveDarkBelowAndRepeatable) {
    const Environment env = neutralEnvironment();
    const glm::vec3 up = env.sample({0, 1, 0}), horizon = env.sample({0, 0, -1}), down = env.sample({0, -1, 0});
    EXPECT_EQ(up.r, up.b);
    EXPECT_GT(up.r, 2.0f * horizon.r);
    EXPECT_GT(horizon.r, 2.0f * down.r);
    EXPECT_EQ(neutralEnvironment().radiance, env.radiance);
    const ImageBasedLight light = prefilterEnvironment(env);
    EXPECT_NEAR(diffuseRadiance(light, {0, 1, 0}).g, 0.8f, 0.15f) << "a white floor-facing-up surface's ambient";
    EXPECT_NEAR(diffuseRadiance(light, {0, 0, -1}).g, 0.4f, 0.1f);
    EXPECT_LT(diffuseRadiance(light, {0, -1, 0}).g, 0.25f);
}

TEST(Environment, radianceHdrRoundTripsWithinRgbePrecision) {
    TempDir dir;
    const Environment env = neutralEnvironment(64, 32);
    writeRadianceHdr(dir.path() / "neutral.hdr", env);
    const Environment back = loadEnvironment(dir.path() / "neutral.hdr");
    ASSERT_EQ(back.width, 64);
    ASSERT_EQ(back.height, 32);
    for (std::size_t i = 0; i < env.radiance.size(); ++i)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(back.radiance[i][c], env.radiance[i][c], env.radiance[i][c] / 64.0f + 1e-3f);
}

TEST(Environment, pngIsDecodedFromSrgb) {
    TempDir dir;
    Image img{4, 2, std::vector<std::uint8_t>(4 * 2 * 4, 255)};
    for (std::size_t i = 0; i < img.rgba.size(); i += 4) img.rgba[i] = img.rgba[i + 1] = img.rgba[i + 2] = 188;
    writePng(dir.path() / "grey.png", img);
    const Environment env = loadEnvironment(dir.path() / "grey.png");
    EXPECT_NEAR(env.at(0, 0).g, 0.5f, 0.01f) << "sRGB 188 is linear one half";
}

TEST(Environment, unusableFilesAreRefusedNamingTheFileAndWhatWasExpected) {
    TempDir dir;
    const std::string missing = messageOf([&] { loadEnvironment(dir.path() / "nope.hdr"); });
    EXPECT_NE(missing.find("nope.hdr"), std::string::npos) << missing;
    EXPECT_NE(missing.find("does not exist"), std::string::npos) << missing;
    const auto garbage = dir.write("garbage.hdr", "not an image");
    const std::string undecodable = messageOf([&] { loadEnvironment(garbage); });
    EXPECT_NE(undecodable.find("garbage.hdr"), std::string::npos) << undecodable;
    EXPECT_NE(undecodable.find("expected a Radiance .hdr"), std::string::npos) << undecodable;
    writePng(dir.path() / "square.png", Image{8, 8, std::vector<std::uint8_t>(8 * 8 * 4, 200)});
    const std::string square = messageOf([&] { loadEnvironment(dir.path() / "square.png"); });
    EXPECT_NE(square.find("twice as wide as high"), std::string::npos) << square;
}

// A uniform environment of radiance L gives irradiance pi * L from every
// direction: E / pi = L.
TEST(ImageBasedLight, uniformEnvironmentGivesItsRadianceAsDiffuse) {
    const ImageBasedLight light = prefilterEnvironment(uniform({0.5f, 1.0f, 2.0f}), 32, 4);
    for (const glm::vec3& n : {glm::vec3(0, 1, 0), glm::vec3(0, -1, 0), glm::normalize(glm::vec3(1, 1, -1))}) {
        const glm::vec3 e = diffuseRadiance(light, n);
        EXPECT_NEAR(e.r, 0.5f, 0.01f);
        EXPECT_NEAR(e.g, 1.0f, 0.02f);
        EXPECT_NEAR(e.b, 2.0f, 0.04f);
    }
    ASSERT_EQ(light.specular.size(), 4u);
    EXPECT_EQ(light.specular[3].width, 4);
    for (const Environment& level : light.specular)
        EXPECT_NEAR(level.at(level.width / 2, level.height / 2).g, 1.0f, 0.02f);
}

// Light from above only: a normal facing up sees it all, one facing down
// none, sideways half (Lambert over a hemisphere).
TEST(ImageBasedLight, irradianceFollowsTheCosineLobe) {
    Environment sky = uniform(glm::vec3(0.0f));
    for (int y = 0; y < sky.height / 2; ++y)
        for (int x = 0; x < sky.width; ++x) sky.radiance[static_cast<std::size_t>(y * sky.width + x)] = glm::vec3(1.0f);
    const ImageBasedLight light = prefilterEnvironment(sky, 32, 4);
    EXPECT_NEAR(diffuseRadiance(light, {0, 1, 0}).r, 1.0f, 0.08f);
    EXPECT_NEAR(diffuseRadiance(light, {0, -1, 0}).r, 0.0f, 0.08f);
    EXPECT_NEAR(diffuseRadiance(light, {1, 0, 0}).r, 0.5f, 0.03f);
}

TEST(ImageBasedLight, rougherLevelsSpreadABrightSpot) {
    Environment spot = uniform(glm::vec3(0.0f));
    spot.radiance[static_cast<std::size_t>(16 * 64 + 32)] = glm::vec3(100.0f);  // near +X on the horizon
    const ImageBasedLight light = prefilterEnvironment(spot, 32, 4);
    const glm::vec3 towards{1, 0, 0}, aside = glm::normalize(glm::vec3(1, 0, 1));
    EXPECT_GT(light.specular[1].sample(towards).r, light.specular[3].sample(towards).r);
    EXPECT_LT(light.specular[1].sample(aside).r, light.specular[3].sample(aside).r);
}

// Karis 2013: for a smooth surface seen head-on the BRDF integrates to F0
// (scale 1, bias 0); a rough one seen head-on keeps about a third of a
// white environment (0.327 by brute-force uniform sampling of the same BRDF
// at roughness 31.5/32).
TEST(ImageBasedLight, splitSumTableHasTheKnownCorners) {
    const SplitSumTable t = splitSumTable(32);
    const glm::vec2 smoothHeadOn = t.scaleBias[static_cast<std::size_t>(0 * 32 + 31)];
    EXPECT_NEAR(smoothHeadOn.x, 1.0f, 0.05f);
    EXPECT_NEAR(smoothHeadOn.y, 0.0f, 0.02f);
    const glm::vec2 roughHeadOn = t.scaleBias[static_cast<std::size_t>(31 * 32 + 31)];
    EXPECT_NEAR(roughHeadOn.x + roughHeadOn.y, 0.327f, 0.03f);
}

TEST(StationConfig, environmentIsNeutralOrAFileBesideTheConfig) {
    TempDir dir;
    const auto neutral = dir.write("a.yaml", "scene:\n  objects:\n    - shape: box\nrender:\n  environment: neutral\n");
    EXPECT_TRUE(loadStationConfig(neutral).render.environment.empty());
    const auto file = dir.write(
        "b.yaml",
        "scene:\n  objects:\n    - shape: box\nrender:\n  environment: hdr/hall.hdr\n  environment_intensity: 0.5\n");
    const StationConfig cfg = loadStationConfig(file);
    EXPECT_EQ(cfg.render.environment, (dir.path() / "hdr/hall.hdr").lexically_normal());
    EXPECT_EQ(cfg.render.environmentIntensity, 0.5f);
    // What `arcomp check` and a reload run: the missing file is named.
    const std::string why = messageOf([&] { Station::preflight(cfg); });
    EXPECT_NE(why.find("hall.hdr"), std::string::npos) << why;
    EXPECT_NE(why.find("does not exist"), std::string::npos) << why;
}
