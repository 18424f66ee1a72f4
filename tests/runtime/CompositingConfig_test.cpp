// The video, matte, compositor and output sections: read with defaults,
// relative paths resolved, mistakes reported with their place.

#include "runtime/config/ConfigError.hpp"
#include "runtime/config/StationConfig.hpp"

#include "../support/TempDir.hpp"

#include <gtest/gtest.h>

using namespace arcomp;
using arcomp::test::TempDir;

namespace {

const char* const kCompositedBox = "scene:\n  objects:\n    - shape: box\n";

std::string issuesOf(const std::filesystem::path& file) {
    try {
        loadStationConfig(file);
    } catch (const ConfigError& e) {
        std::string s;
        for (const ConfigIssue& i : e.issues) s += i.format() + "\n";
        return s;
    }
    return {};
}

}  // namespace

TEST(CompositingConfig, absentSectionsMeanNoVideoNoMatteNoOutput) {
    TempDir dir;
    const StationConfig cfg = loadStationConfig(dir.write("s.yaml", kCompositedBox));
    EXPECT_FALSE(cfg.compositing.video.has_value());
    EXPECT_EQ(cfg.compositing.matte.kind, MatteKind::None);
    EXPECT_TRUE(cfg.compositing.output.pngDir.empty());
    EXPECT_TRUE(cfg.compositing.output.videoFile.empty());
    EXPECT_EQ(cfg.compositing.compositor.holdout, HoldoutMesh::Silhouette);
}

TEST(CompositingConfig, readsEverySectionAndResolvesPathsAgainstTheConfig) {
    TempDir dir;
    const auto file = dir.write("site/s.yaml", std::string(kCompositedBox) + R"(
video:
  source: file
  path: clips/walk.avi
  fallback: pattern
  size: [320, 240]
matte:
  kind: chroma
  chroma:
    key_rgb: [10, 200, 20]
    similarity: 0.1
    smoothness: 0.05
    spill: 0.2
  background:
    method: cnt
    scale: 0.25
compositor:
  person_plane_m: 7.5
  holdout: full
  backdrop: color
  backdrop_color: [0, 0, 0, 1]
output:
  png_dir: out/frames
  video_file: out/composite.avi
  video_fourcc: XVID
)");
    const StationConfig cfg = loadStationConfig(file);
    ASSERT_TRUE(cfg.compositing.video.has_value());
    EXPECT_EQ(cfg.compositing.video->kind, SourceKind::File);
    EXPECT_EQ(cfg.compositing.video->path, (dir.path() / "site/clips/walk.avi").string());
    EXPECT_EQ(cfg.compositing.video->fallback.kind, FallbackKind::Pattern);
    EXPECT_EQ(cfg.compositing.video->width, 320);
    EXPECT_EQ(cfg.compositing.matte.kind, MatteKind::Chroma);
    EXPECT_EQ(cfg.compositing.matte.chroma.keyBgr, cv::Vec3b(20, 200, 10));
    EXPECT_FLOAT_EQ(cfg.compositing.matte.chroma.spill, 0.2f);
    EXPECT_EQ(cfg.compositing.matte.background.method, BackgroundMethod::Cnt);
    EXPECT_DOUBLE_EQ(cfg.compositing.matte.background.scale, 0.25);
    EXPECT_DOUBLE_EQ(cfg.compositing.matte.background.consensus.fps, 30.0) << "the video's rate";
    EXPECT_FLOAT_EQ(cfg.compositing.compositor.personPlaneMetres, 7.5f);
    EXPECT_EQ(cfg.compositing.compositor.holdout, HoldoutMesh::Full);
    EXPECT_FALSE(cfg.compositing.compositor.backdropVideo);
    EXPECT_EQ(cfg.compositing.output.pngDir, dir.path() / "site/out/frames");
    EXPECT_EQ(cfg.compositing.output.videoFourcc, "XVID");
}

TEST(CompositingConfig, reportsMistakesWithTheirPlace) {
    TempDir dir;
    const auto file = dir.write("s.yaml", std::string(kCompositedBox) + R"(video:
  source: webcam
matte:
  kind: background
  background:
    method: mog2
    scale: 3
    colour: red
compositor:
  person_plane_m: -1
output:
  video_fourcc: MPEG4
)");
    const std::string issues = issuesOf(file);
    EXPECT_NE(issues.find("s.yaml:5:"), std::string::npos) << issues;   // source: webcam
    EXPECT_NE(issues.find("video.path"), std::string::npos) << issues;  // file needs a path
    EXPECT_NE(issues.find("matte.background.scale"), std::string::npos) << issues;
    EXPECT_NE(issues.find("matte.background.colour"), std::string::npos) << issues;  // unknown key
    EXPECT_NE(issues.find("compositor.person_plane_m"), std::string::npos) << issues;
    EXPECT_NE(issues.find("video_fourcc"), std::string::npos) << issues;
}

TEST(CompositingConfig, backgroundMatteDefaultsToConsensusWithItsSettingsInSeconds) {
    TempDir dir;
    const StationConfig plain = loadStationConfig(dir.write("plain.yaml", std::string(kCompositedBox) + R"(video:
  source: pattern
  fps: 12
matte:
  kind: background
)"));
    const BackgroundSpec& d = plain.compositing.matte.background;
    EXPECT_EQ(d.method, BackgroundMethod::Consensus);
    EXPECT_DOUBLE_EQ(d.consensus.fps, 12.0) << "seconds turn into frames at the video's rate";

    const StationConfig tuned = loadStationConfig(dir.write("tuned.yaml", std::string(kCompositedBox) + R"(matte:
  kind: background
  background:
    samples: 16
    colour_radius: 30
    shadow_darkest: 0.3
    absorb_s: 300
    warmup_s: 4
    fps: 15
    edge_radius_px: 0
)"));
    const ConsensusSpec& c = tuned.compositing.matte.background.consensus;
    EXPECT_EQ(c.samples, 16);
    EXPECT_DOUBLE_EQ(c.colourRadius, 30.0);
    EXPECT_DOUBLE_EQ(c.shadowDarkest, 0.3);
    EXPECT_DOUBLE_EQ(c.absorbSeconds, 300.0);
    EXPECT_DOUBLE_EQ(c.warmupSeconds, 4.0);
    EXPECT_DOUBLE_EQ(c.fps, 15.0);
    EXPECT_EQ(c.edgeRadiusPx, 0);

    const std::string issues = issuesOf(dir.write("bad.yaml", std::string(kCompositedBox) + R"(matte:
  kind: background
  background:
    samples: 8
    matches: 9
    shadow_darkest: 0.9
    shadow_lightest: 0.5
    absorb_s: -1
)"));
    EXPECT_NE(issues.find("matte.background.matches"), std::string::npos) << issues;
    EXPECT_NE(issues.find("matte.background.shadow_darkest"), std::string::npos) << issues;
    EXPECT_NE(issues.find("matte.background.absorb_s"), std::string::npos) << issues;
}

TEST(CompositingConfig, masksPersonDepthAndShadowAreReadWithTheirDefaults) {
    TempDir dir;
    std::filesystem::create_directories(dir.path() / "masks");
    const StationConfig plain = loadStationConfig(dir.write("plain.yaml", kCompositedBox));
    EXPECT_TRUE(plain.compositing.compositor.personDepthFromFeet);
    EXPECT_FALSE(plain.compositing.compositor.shadow.enabled.has_value());  // decided by the camera
    const StationConfig cfg = loadStationConfig(dir.write("s.yaml", std::string(kCompositedBox) + R"(matte:
  kind: masks
  masks: {folder: masks}
compositor:
  person_depth: plane
  shadow: {enabled: true, light: [0, 2, 0], strength: 0.3}
)"));
    EXPECT_EQ(cfg.compositing.matte.kind, MatteKind::Masks);
    EXPECT_EQ(cfg.compositing.matte.masks.folder, dir.path() / "masks");
    EXPECT_FALSE(cfg.compositing.compositor.personDepthFromFeet);
    EXPECT_EQ(cfg.compositing.compositor.shadow.enabled, std::optional<bool>(true));
    EXPECT_FLOAT_EQ(cfg.compositing.compositor.shadow.light.y, 1.0f);  // made unit length
    EXPECT_FLOAT_EQ(cfg.compositing.compositor.shadow.strength, 0.3f);
}

TEST(CompositingConfig, aMasksFolderThatIsNotThereAndALightBelowTheFloorAreRefused) {
    TempDir dir;
    const std::string issues = issuesOf(dir.write("s.yaml", std::string(kCompositedBox) + R"(matte:
  kind: masks
  masks: {folder: nowhere}
compositor:
  shadow: {light: [1, 0.05, 0]}
)"));
    EXPECT_NE(issues.find("matte.masks.folder"), std::string::npos) << issues;
    EXPECT_NE(issues.find("compositor.shadow.light"), std::string::npos) << issues;
    const std::string noFolder = issuesOf(dir.write("t.yaml", std::string(kCompositedBox) + "matte:\n  kind: masks\n"));
    EXPECT_NE(noFolder.find("matte.masks"), std::string::npos) << noFolder;
}
