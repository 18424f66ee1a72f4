// The config's zones: floor polygons and circles in metres with a
// calibrated camera, picture rectangles without one, and each mistake at
// its line: a polygon that crosses itself or has no area, a name used twice,
// metres without a calibration, a zone the camera cannot see.

#include "runtime/config/CameraFile.hpp"
#include "runtime/config/StationConfig.hpp"
#include "runtime/zones/Zone.hpp"

#include "tests/support/BoxStation.hpp"
#include "tests/support/ConfigIssues.hpp"
#include "tests/support/TempDir.hpp"

#include <gtest/gtest.h>

#include <filesystem>

using namespace arcomp;
using arcomp::test::TempDir;

namespace {

// The demo's calibrated camera beside the config, and a floor point it
// sees: the floor under the picture's centre.
struct CalibratedDir {
    TempDir dir;
    glm::vec2 seen{0.0f};
    CalibratedDir() {
        const auto camera = std::filesystem::path(ARCOMP_SOURCE_DIR) / "configs/cameras/vtest.yaml";
        std::filesystem::copy_file(camera, dir.path() / "camera.yaml");
        const CalibratedCamera c = readCameraFile(camera);
        const auto floor = c.floorPointAt(glm::dvec2(c.intrinsics.imageSize) * 0.5);
        if (floor) seen = {static_cast<float>(floor->x), static_cast<float>(floor->z)};
    }
    std::string station(const std::string& zones) const {
        return "scene:\n  objects:\n    - {shape: box, position: [0, 0.5, 0]}\ncamera: {calibration: "
               "camera.yaml}\nzones:\n" +
               zones;
    }
    static std::string at(glm::vec2 p) { return "[" + std::to_string(p.x) + ", " + std::to_string(p.y) + "]"; }
};

}  // namespace

TEST(Zone, signedDistanceIsNegativeInsideAPolygonAndACircle) {
    const Zone square{.name = "sq",
                      .space = ZoneSpace::Floor,
                      .polygon = {{0, 0}, {2, 0}, {2, 2}, {0, 2}},
                      .center = {},
                      .radius = 0.0f,
                      .enterMargin = 0.0f,
                      .leaveMargin = 0.0f};
    EXPECT_NEAR(signedDistance(square, {1.0f, 1.0f}), -1.0f, 1e-6f);
    EXPECT_NEAR(signedDistance(square, {3.0f, 1.0f}), 1.0f, 1e-6f);
    EXPECT_NEAR(signedDistance(square, {2.0f, 0.5f}), 0.0f, 1e-6f);
    const Zone disc{.name = "disc",
                    .space = ZoneSpace::Floor,
                    .polygon = {},
                    .center = {1, 1},
                    .radius = 0.5f,
                    .enterMargin = 0.0f,
                    .leaveMargin = 0.0f};
    EXPECT_NEAR(signedDistance(disc, {1.0f, 1.25f}), -0.25f, 1e-6f);
    EXPECT_NEAR(signedDistance(disc, {2.0f, 1.0f}), 0.5f, 1e-6f);
}

TEST(Zone, aPolygonThatCrossesItselfOrHasNoAreaIsNamed) {
    EXPECT_EQ(polygonProblem({{0, 0}, {1, 0}, {1, 1}}), "");
    EXPECT_NE(polygonProblem({{0, 0}, {1, 1}, {1, 0}, {0, 1}}).find("crosses itself"), std::string::npos);
    EXPECT_NE(polygonProblem({{0, 0}, {1, 1}, {2, 2}}).find("no area"), std::string::npos);
    EXPECT_NE(polygonProblem({{0, 0}, {1, 1}}).find("at least 3"), std::string::npos);
}

TEST(ZoneConfig, readsFloorZonesWithACalibrationAndPictureZonesWithout) {
    CalibratedDir c;
    const glm::vec2 s = c.seen;
    const StationConfig cfg = loadStationConfig(c.dir.write(
        "s.yaml", c.station("  - {name: front, polygon: [" + CalibratedDir::at(s + glm::vec2(-1, -1)) + ", " +
                            CalibratedDir::at(s + glm::vec2(1, -1)) + ", " + CalibratedDir::at(s + glm::vec2(0, 1)) +
                            "]}\n  - {name: spot, circle: {center: " + CalibratedDir::at(s) +
                            ", radius: 0.5}}\n  - {name: door, image_rect: {min: [0, 0.5], max: [0.2, 1]}}\n")));
    ASSERT_EQ(cfg.zones.size(), 3u);
    EXPECT_EQ(cfg.zones[0].name, "front");
    EXPECT_EQ(cfg.zones[0].polygon.size(), 3u);
    EXPECT_EQ(cfg.zones[1].radius, 0.5f);
    EXPECT_EQ(cfg.zones[2].space, ZoneSpace::Image);
    EXPECT_LT(signedDistance(cfg.zones[2], {0.1f, 0.75f}), 0.0f);

    TempDir plain;
    const StationConfig uncalibrated = loadStationConfig(
        plain.write("s.yaml", std::string(test::kBoxStation) +
                                  "zones:\n  - {name: door, image_rect: {min: [0, 0], max: [1, 1]}}\n"));
    ASSERT_EQ(uncalibrated.zones.size(), 1u);
}

TEST(ZoneConfig, reportsEachMistakeAtItsLine) {
    CalibratedDir c;
    const glm::vec2 s = c.seen;
    const std::string far = CalibratedDir::at(s + glm::vec2(0.0f, 500.0f));
    const auto yaml =
        c.station("  - {name: bow, polygon: [[0, 0], [1, 1], [1, 0], [0, 1]]}\n"  // +1: crosses itself
                  "  - {name: line, polygon: [[0, 0], [1, 1], [2, 2]]}\n"         // +2: no area
                  "  - {name: spot, circle: {center: " +
                  CalibratedDir::at(s) +
                  ", radius: 0.5}}\n"
                  "  - {name: spot, circle: {center: " +
                  CalibratedDir::at(s) +
                  ", radius: 0.2}}\n"  // +4: duplicate
                  "  - {name: away, circle: {center: " +
                  far +
                  ", radius: 0.5}}\n"  // +5: not seen
                  "  - {name: both, image_rect: {min: [0, 0], max: [1, 1]}, circle: {center: [0, 0], radius: 1}}\n"
                  "  - {name: flipped, image_rect: {min: [0.5, 0.5], max: [0.2, 1]}}\n"
                  "  - {name: \"\", circle: {center: " +
                  CalibratedDir::at(s) + ", radius: 0.5}}\n");  // +7: no name
    const auto issues = test::configIssues(c.dir.write("s.yaml", yaml));
    const int first = test::lineOf(yaml, "name: bow");
    EXPECT_TRUE(test::hasIssue(issues, first, "crosses itself")) << test::describe(issues);
    EXPECT_TRUE(test::hasIssue(issues, first + 1, "has no area")) << test::describe(issues);
    EXPECT_TRUE(test::hasIssue(issues, first + 3, "the name is used by an earlier zone")) << test::describe(issues);
    EXPECT_TRUE(test::hasIssue(issues, first + 4, "wholly outside the calibrated camera's view"))
        << test::describe(issues);
    EXPECT_TRUE(test::hasIssue(issues, first + 5, "give one shape")) << test::describe(issues);
    EXPECT_TRUE(test::hasIssue(issues, first + 6, "below and left of max")) << test::describe(issues);
    EXPECT_TRUE(test::hasIssue(issues, first + 7, "name: empty")) << test::describe(issues);
    EXPECT_EQ(issues.size(), 7u) << test::describe(issues);

    TempDir plain;
    const auto metres = test::configIssues(plain.write(
        "s.yaml", std::string(test::kBoxStation) + "zones:\n  - {name: front, circle: {center: [0, 1], radius: 1}}\n"));
    ASSERT_EQ(metres.size(), 1u) << test::describe(metres);
    EXPECT_NE(metres[0].message.find("needs camera.calibration"), std::string::npos) << test::describe(metres);
}
