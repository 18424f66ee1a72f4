// arcomp calibrate floor: a known camera's view of floor marks gives back
// that camera, whether the marks are given by hand or are an ArUco marker's
// corners; too few, collinear or malformed points, a marker not in view, or
// no lens, are refused with exit 2 and say what is wrong.
#include "../support/TempDir.hpp"
#include "runtime/config/CameraFile.hpp"
#include "tests/support/Shell.hpp"
#include "tools/bench/scenes/SyntheticCamera.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include <cstdio>

using arcomp::test::TempDir;

namespace arcomp {
namespace {

// 4.2 m up at x = 1, z = 12, looking along -z and 25 degrees down; a 60 degree lens.
CalibratedCamera trueCamera() {
    CalibratedCamera c;
    const double f = 0.5 * 480 / std::tan(glm::radians(60.0) / 2.0);
    c.intrinsics = {.imageSize = {640, 480}, .fx = f, .fy = f, .cx = 319.5, .cy = 239.5, .distortion = {}};
    const double tilt = glm::radians(25.0);
    const glm::dvec3 forward(0.0, -std::sin(tilt), -std::cos(tilt)), right(1.0, 0.0, 0.0);
    c.rotation = glm::transpose(glm::dmat3(right, glm::cross(forward, right), forward));
    c.translation = -c.rotation * glm::dvec3(1.0, 4.2, 12.0);
    return c;
}

std::string pointsSeenBy(const CalibratedCamera& c, const std::vector<glm::dvec2>& floor) {
    std::string text;
    for (const glm::dvec2& xz : floor) {
        const glm::dvec2 uv = c.project({xz.x, 0.0, xz.y});
        char item[96];
        std::snprintf(item, sizeof item, "%s%.3f,%.3f=%g,%g", text.empty() ? "" : ";", uv.x, uv.y, xz.x, xz.y);
        text += item;
    }
    return text;
}

test::ShellResult calibrateFloor(const std::string& args) { return test::arcompCommand("calibrate floor " + args); }

// A 50 degree lens 3 m above the floor at x = 0.4, looking along -z and 40
// degrees down at the floor's origin, where marker 7 (0.5 m) lies; marker 3
// lies 1 m to its right and 0.6 m nearer.
constexpr double kHeight = 3.0, kTilt = 40.0, kX = 0.4;
const double kZ = kHeight / std::tan(kTilt * CV_PI / 180.0);

cv::Mat floorPhoto(const std::vector<FloorMarkerSpec>& markers, double size = 0.5) {
    const double f = 0.5 * 480 / std::tan(25.0 * CV_PI / 180.0);
    const SyntheticCamera camera({.size = {640, 480}, .fx = f, .fy = f, .cx = 319.5, .cy = 239.5, .distortion = {}});
    const cv::Mat floor =
        floorWithMarkers(cv::aruco::getPredefinedDictionary(cv::aruco::DICT_4X4_50), markers, size, 3.0, 400);
    return camera.photograph(floor, 1.0 / 400, {-1.5, -1.5}, floorToCamera(kX, kHeight, kZ, kTilt));
}

}  // namespace

TEST(CalibrateFloor, sixFloorMarksGiveBackTheCameraThatSawThem) {
    TempDir dir;
    const auto image = dir.path() / "plate.png";
    cv::imwrite(image.string(), cv::Mat(480, 640, CV_8UC3, cv::Scalar(90, 110, 100)));
    const CalibratedCamera truth = trueCamera();
    const std::string points = pointsSeenBy(truth, {{-2, 0}, {3, 0}, {-2, 4}, {3, 4}, {0, 7}, {1, 2}});
    const auto out = dir.path() / "camera.yaml";
    const auto r = calibrateFloor(image.string() + " --fovy-deg 60 --points \"" + points + "\" --out " + out.string() +
                                  " --preview " + (dir.path() / "preview.png").string());
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("4.20 m above the floor"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("tilted 25.0 degrees down"), std::string::npos) << r.out;

    const CalibratedCamera found = readCameraFile(out);
    EXPECT_NEAR(found.position().x, 1.0, 0.01);
    EXPECT_NEAR(found.position().y, 4.2, 0.01);
    EXPECT_NEAR(found.position().z, 12.0, 0.01);
    EXPECT_NEAR(found.tiltDegrees(), 25.0, 0.05);
    const glm::dvec2 far = found.project({-4.0, 0.0, -10.0}), expected = truth.project({-4.0, 0.0, -10.0});
    EXPECT_NEAR(far.x, expected.x, 0.5);
    EXPECT_NEAR(far.y, expected.y, 0.5);
    EXPECT_FALSE(cv::imread((dir.path() / "preview.png").string()).empty());
}

struct FloorInputCase {
    const char* name;
    const char* points;  // for trueCamera's image, or literally when it holds no '@'
    const char* lens;
    const char* expected;
};

class CalibrateFloorRefuses : public ::testing::TestWithParam<FloorInputCase> {};

TEST_P(CalibrateFloorRefuses, withExitTwoAndTheReason) {
    TempDir dir;
    const auto image = dir.path() / "plate.png";
    cv::imwrite(image.string(), cv::Mat(480, 640, CV_8UC3, cv::Scalar::all(0)));
    const auto r = calibrateFloor(image.string() + " " + GetParam().lens + " --points \"" + GetParam().points +
                                  "\" --out " + (dir.path() / "camera.yaml").string());
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_NE(r.out.find(GetParam().expected), std::string::npos) << r.out;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "camera.yaml"));
}

INSTANTIATE_TEST_SUITE_P(
    BadInput, CalibrateFloorRefuses,
    ::testing::Values(FloorInputCase{"tooFew", "100,400=0,0;500,400=3,0;300,200=1,6", "--fovy-deg 60",
                                     "3 given; the floor needs at least 4"},
                      FloorInputCase{"collinear", "100,400=0,0;200,380=1,1;300,360=2,2;400,340=3,3", "--fovy-deg 60",
                                     "on one line"},
                      FloorInputCase{"malformed", "100,400=0,0;500,400:3,0;300,200=1,6;320,300=1,3", "--fovy-deg 60",
                                     "item 2 (\"500,400:3,0\") is not u,v=x,z"},
                      FloorInputCase{"outsideTheImage", "100,400=0,0;900,400=3,0;300,200=1,6;320,300=1,3",
                                     "--fovy-deg 60", "outside the 640x480 image"},
                      FloorInputCase{"noLens", "100,400=0,0;500,400=3,0;300,200=1,6;320,300=1,3", "", "give the lens"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(CalibrateFloor, anImageThatIsNotOneIsRefused) {
    TempDir dir;
    const auto r = calibrateFloor(dir.write("plate.png", "not a picture").string() +
                                  " --fovy-deg 60 --points \"1,1=0,0\" --out " + (dir.path() / "c.yaml").string());
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_NE(r.out.find("neither an image nor a video"), std::string::npos) << r.out;
}

TEST(CalibrateFloor, aMarkerOnTheFloorIsItsOriginAndGivesTheCameraOverIt) {
    TempDir dir;
    const auto image = dir.path() / "plate.png";
    ASSERT_TRUE(cv::imwrite(image.string(), floorPhoto({{7, 0.0, 0.0}, {3, 1.0, 0.6}})));
    const auto out = dir.path() / "camera.yaml";
    const auto r = calibrateFloor(image.string() + " --fovy-deg 50 --marker 7 --marker-size 0.5 --out " + out.string());
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("floor: the corners of DICT_4X4_50 marker 7 (0.5 m)"), std::string::npos) << r.out;

    const CalibratedCamera found = readCameraFile(out);
    EXPECT_NEAR(found.heightMetres(), kHeight, 0.03 * kHeight);
    EXPECT_NEAR(found.tiltDegrees(), kTilt, 1.5);
    // Where the camera stands says where the marker put the origin and
    // which way it turned x and z.
    EXPECT_NEAR(found.position().x, kX, 0.1);
    EXPECT_NEAR(found.position().z, kZ, 0.1);
    EXPECT_EQ(r.out.find("warning"), std::string::npos) << r.out;
}

TEST(CalibrateFloor, aMarkerTooSmallInThePictureToPlaceTheCameraWellIsWarnedAbout) {
    TempDir dir;
    const auto image = dir.path() / "plate.png";
    ASSERT_TRUE(cv::imwrite(image.string(), floorPhoto({{7, 0.0, 0.0}}, 0.2)));
    const auto r = calibrateFloor(image.string() + " --fovy-deg 50 --marker 7 --marker-size 0.2 --out " +
                                  (dir.path() / "c.yaml").string());
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("warning: marker 7 spans only"), std::string::npos) << r.out;
}

struct MarkerInputCase {
    const char* name;
    const char* args;
    const char* expected;
};

class CalibrateFloorByMarkerRefuses : public ::testing::TestWithParam<MarkerInputCase> {};

// The photo shows markers 3 and 12, not 7.
TEST_P(CalibrateFloorByMarkerRefuses, withExitTwoAndTheReason) {
    TempDir dir;
    const auto image = dir.path() / "plate.png";
    ASSERT_TRUE(cv::imwrite(image.string(), floorPhoto({{3, 0.0, 0.0}, {12, 1.0, 0.6}})));
    const auto r = calibrateFloor(image.string() + " --fovy-deg 50 " + GetParam().args + " --out " +
                                  (dir.path() / "camera.yaml").string());
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_NE(r.out.find(std::string("arcomp calibrate floor: ") + GetParam().expected), std::string::npos) << r.out;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "camera.yaml"));
}

INSTANTIATE_TEST_SUITE_P(
    BadInput, CalibrateFloorByMarkerRefuses,
    ::testing::Values(MarkerInputCase{"notInView", "--marker 7 --marker-size 0.5",
                                      "--marker 7: not in the image; it shows DICT_4X4_50 markers 3, 12"},
                      MarkerInputCase{"notInTheDictionary", "--marker 60 --marker-size 0.5",
                                      "--marker 60: DICT_4X4_50 has IDs 0 to 49"},
                      MarkerInputCase{"otherDictionary", "--marker 3 --marker-size 0.5 --dictionary DICT_6X6_250",
                                      "--marker 3: not in the image; it shows no DICT_6X6_250 markers at all"},
                      MarkerInputCase{"unknownDictionary", "--marker 3 --marker-size 0.5 --dictionary DICT_9X9_7",
                                      "--dictionary DICT_9X9_7: not an OpenCV ArUco dictionary"},
                      MarkerInputCase{"noSize", "--marker 3", "--marker 3: give its --marker-size"},
                      MarkerInputCase{"markerAndPoints",
                                      "--marker 3 --marker-size 0.5 --points \"1,1=0,0;2,2=1,0;3,1=1,1;1,3=0,1\"",
                                      "give the floor marks by --points or by --marker, not both"},
                      MarkerInputCase{"neither", "", "give the floor marks: --points"}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace arcomp
