// Config errors: every class reported with its line and column, all at once.

#include "runtime/config/ConfigError.hpp"
#include "runtime/config/StationConfig.hpp"

#include "../support/ConfigIssues.hpp"
#include "../support/TempDir.hpp"

#include <gtest/gtest.h>

using namespace arcomp;
using arcomp::test::configIssues;
using arcomp::test::describe;
using arcomp::test::hasIssue;
using arcomp::test::TempDir;

namespace {}  // namespace

TEST(StationConfig, readsAValidConfigWithRelativePaths) {
    TempDir dir;
    dir.write("models/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const auto file = dir.write("station.yaml", R"(scene:
  objects:
    - model: models/tri.obj
      position: [1, 2, 3]
      scale: 2
    - shape: box
      size: [1, 2, 1]
      color: [1, 0, 0, 1]
camera:
  eye: [0, 1, 5]
  target: [0, 1, 0]
  size: [640, 480]
render:
  shading: flat
  gl: es3
)");
    const StationConfig cfg = loadStationConfig(file);
    ASSERT_EQ(cfg.objects.size(), 2u);
    EXPECT_EQ(cfg.objects[0].model, (dir.path() / "models/tri.obj").lexically_normal());
    EXPECT_EQ(cfg.objects[0].scale, glm::vec3(2.0f));
    EXPECT_EQ(cfg.objects[1].shape, "box");
    EXPECT_EQ(cfg.camera.size, glm::ivec2(640, 480));
    EXPECT_EQ(cfg.render.shading, Shading::Flat);
    EXPECT_EQ(cfg.render.gl, "es3");
}

TEST(StationConfig, reportsEveryErrorClassWithLineAndColumn) {
    TempDir dir;
    const auto file = dir.write("bad.yaml", R"(scene:
  objects:
    - model: missing.glb
      colour: [1, 0, 0, 1]
    - shape: box
      size: [1, two, 1]
camera:
  eye: [0, 1, 5]
  target: [0, 1, 0]
  fovy_deg: 500
render:
  shading: shiny
)");
    const auto issues = configIssues(file);
    EXPECT_TRUE(hasIssue(issues, 3, "does not exist", 14)) << describe(issues);                // missing file
    EXPECT_TRUE(hasIssue(issues, 4, "unknown key", 7)) << describe(issues);                    // unknown key
    EXPECT_TRUE(hasIssue(issues, 6, "expected a list of 3 numbers", 13)) << describe(issues);  // wrong type
    EXPECT_TRUE(hasIssue(issues, 10, "out of range", 13)) << describe(issues);                 // bad number
    EXPECT_TRUE(hasIssue(issues, 12, "is not one of unlit, flat, gouraud, phong", 12)) << describe(issues);
    EXPECT_EQ(issues.size(), 5u) << describe(issues);
}

TEST(StationConfig, reportsAMissingRequiredKeyAtItsParent) {
    TempDir dir;
    const auto issues = configIssues(dir.write("nokeys.yaml", "render:\n  shading: flat\n"));
    ASSERT_EQ(issues.size(), 1u) << describe(issues);
    EXPECT_NE(issues[0].message.find("scene: required key is missing"), std::string::npos);
    EXPECT_EQ(issues[0].line, 1);
}

TEST(StationConfig, reportsSyntaxErrorsAndUnreadableFiles) {
    TempDir dir;
    const auto syntax = configIssues(dir.write("syntax.yaml", "scene:\n  objects: [\n"));
    ASSERT_EQ(syntax.size(), 1u);
    EXPECT_NE(syntax[0].message.find("YAML syntax"), std::string::npos);
    EXPECT_GT(syntax[0].line, 0);
    const auto missing = configIssues(dir.path() / "nope.yaml");
    ASSERT_EQ(missing.size(), 1u);
    EXPECT_NE(missing[0].format().find("nope.yaml: cannot be read"), std::string::npos);
    const auto notMap = configIssues(dir.write("list.yaml", "- 1\n- 2\n"));
    ASSERT_EQ(notMap.size(), 1u);
}

TEST(StationConfig, readsObjectLodMotionAndGaze) {
    TempDir dir;
    dir.write("gaze.csv", "time,eye_x,eye_y,eye_z,gaze_x,gaze_y,gaze_z\n0,0,0,0,0,0,-1\n1,0,0,0,0.2,0,-1\n");
    const auto file = dir.write("station.yaml", R"(scene:
  objects:
    - shape: sphere
      lod: {policy: screen_size, ratios: [1, 0.25, 0.05], thresholds: [200, 40], fade_s: 0.2}
      motion: {velocity: [0.5, 0, 0], range_m: 3}
gaze: {source: track, track: gaze.csv}
)");
    const StationConfig cfg = loadStationConfig(file);
    const ObjectConfig& o = cfg.objects.at(0);
    EXPECT_EQ(o.lodPolicy, LodPolicy::ScreenSize);
    EXPECT_EQ(o.lodRatios, (std::vector<float>{1.0f, 0.25f, 0.05f}));
    EXPECT_EQ(o.lodThresholds, (std::vector<float>{200.0f, 40.0f}));
    EXPECT_FLOAT_EQ(o.lodFadeSeconds, 0.2f);
    EXPECT_EQ(o.velocity, glm::vec3(0.5f, 0.0f, 0.0f));
    EXPECT_FLOAT_EQ(o.rangeMetres, 3.0f);
    EXPECT_EQ(cfg.gaze.kind, GazeKind::Track);
    EXPECT_EQ(cfg.gaze.track.filename(), "gaze.csv");
}

TEST(StationConfig, reportsInconsistentLodAndMissingGazeTrack) {
    TempDir dir;
    const auto issues = configIssues(dir.write("bad.yaml", R"(scene:
  objects:
    - shape: box
      lod: {ratios: [1, 0.5], thresholds: [10, 20]}
    - shape: box
      lod: {policy: distance, ratios: [1, 2]}
gaze: {source: track, track: nowhere.csv}
)"));
    EXPECT_TRUE(hasIssue(issues, 4, "one threshold fewer", 12)) << describe(issues);
    EXPECT_TRUE(hasIssue(issues, 6, "ratios: expected numbers from 0.0001 to 1", 43)) << describe(issues);
    EXPECT_TRUE(hasIssue(issues, 6, "'thresholds' is required", 12)) << describe(issues);
    EXPECT_TRUE(hasIssue(issues, 7, "nowhere.csv' does not exist", 30)) << describe(issues);
}
