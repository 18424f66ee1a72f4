// arcomp calibrate intrinsics: photos of a chessboard, or a video of a
// ChArUco board, taken through a known lens give that lens back, and the
// lens file it writes is what `calibrate floor --intrinsics` takes. No board,
// too few views, a board too small in the picture, bad board sizes and a
// missing input are refused with exit 2 and say what is wrong.
#include "../support/TempDir.hpp"
#include "runtime/config/CameraFile.hpp"
#include "tests/support/Shell.hpp"
#include "tools/bench/scenes/SyntheticCamera.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include <cstdio>

using arcomp::test::TempDir;

namespace arcomp {
namespace {

// The lens the photos are taken with: pixels a little taller than wide,
// the principal point off centre, barrel distortion.
const SyntheticLens kLens{.size = {640, 480}, .fx = 610, .fy = 600, .cx = 326, .cy = 234, .distortion = {-0.08}};

const SyntheticCamera& camera() {
    static const SyntheticCamera c(kLens);
    return c;
}

// 9 x 6 squares of 25 mm, drawn at 40 texels a square with one square of
// margin; for ChArUco, 18 mm markers.
constexpr int kCols = 9, kRows = 6, kTexels = 40;
constexpr double kSquare = 0.025, kMarker = 0.018;

// Where the board is in a view: tilted about the camera's x and y, turned
// about its own normal (degrees), and where its centre is (metres, camera frame).
struct BoardPose {
    double tiltX, tiltY, turn;
    cv::Vec3d centre;
};

// Twelve views, each tilted up to 35 degrees a different way, the board
// filling a tenth of the picture or more.
const BoardPose kPoses[] = {
    {0, 0, 0, {0, 0, 0.42}},     {25, 0, 5, {0.03, 0.015, 0.40}},     {-25, 0, -5, {-0.03, -0.015, 0.40}},
    {0, 25, 10, {0, 0, 0.45}},   {0, -25, -10, {0.02, 0.01, 0.38}},   {20, 20, 0, {-0.02, -0.01, 0.42}},
    {-20, 20, 15, {0, 0, 0.40}}, {20, -20, -15, {0.03, 0.015, 0.44}}, {-20, -20, 30, {-0.03, -0.015, 0.40}},
    {35, 10, 0, {0, 0, 0.42}},   {10, -35, 90, {0.01, 0.005, 0.40}},  {-30, -15, -30, {0, 0, 0.38}},
};

// The board's plane to the camera for a pose; `farther` moves the board
// away along its line of sight (2.8: an eighth of the area in the picture).
cv::Matx33d placed(const BoardPose& p, double farther = 1.0) {
    cv::Matx33d rx, ry, rz;
    cv::Rodrigues(cv::Vec3d(p.tiltX * CV_PI / 180, 0, 0), rx);
    cv::Rodrigues(cv::Vec3d(0, p.tiltY * CV_PI / 180, 0), ry);
    cv::Rodrigues(cv::Vec3d(0, 0, p.turn * CV_PI / 180), rz);
    const cv::Matx33d r = rx * ry * rz;
    const cv::Vec3d boardCentre(kCols * kSquare / 2, kRows * kSquare / 2, 0);
    const cv::Vec3d t = p.centre * farther - r * boardCentre;
    return cv::Matx33d(r(0, 0), r(0, 1), t[0], r(1, 0), r(1, 1), t[1], r(2, 0), r(2, 1), t[2]);
}

cv::Mat photo(const cv::Mat& board, const BoardPose& pose, double farther = 1.0) {
    return camera().photograph(board, kSquare / kTexels, {-kSquare, -kSquare}, placed(pose, farther));
}

cv::Ptr<cv::aruco::CharucoBoard> charucoBoard() {
    return cv::aruco::CharucoBoard::create(kCols, kRows, static_cast<float>(kSquare), static_cast<float>(kMarker),
                                           cv::aruco::getPredefinedDictionary(cv::aruco::DICT_4X4_50));
}

// The first `count` views of the chessboard as view00.png, view01.png, ...
void writeChessboardPhotos(const std::filesystem::path& folder, int count, double farther = 1.0) {
    std::filesystem::create_directories(folder);
    const cv::Mat board = chessboardTexture(kCols, kRows, kTexels);
    for (int i = 0; i < count; ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "view%02d.png", i);
        ASSERT_TRUE(cv::imwrite((folder / name).string(), photo(board, kPoses[i % std::size(kPoses)], farther)));
    }
}

test::ShellResult calibrateIntrinsics(const std::string& args) {
    return test::arcompCommand("calibrate intrinsics " + args);
}

// The reprojection error the command printed, or -1.
double printedRms(const std::string& out) {
    const std::size_t at = out.find("reprojection ");
    double rms = -1.0;
    if (at == std::string::npos || std::sscanf(out.c_str() + at, "reprojection %lf px RMS", &rms) != 1) return -1.0;
    return rms;
}

void expectTheLens(const std::filesystem::path& file) {
    const CameraIntrinsics k = readCameraFile(file).intrinsics;
    EXPECT_EQ(k.imageSize, glm::ivec2(640, 480));
    EXPECT_NEAR(k.fx, kLens.fx, 0.02 * kLens.fx);
    EXPECT_NEAR(k.fy, kLens.fy, 0.02 * kLens.fy);
    EXPECT_NEAR(k.cx, kLens.cx, 3.0);
    EXPECT_NEAR(k.cy, kLens.cy, 3.0);
    EXPECT_NEAR(k.distortion[0], kLens.distortion[0], 0.02);
}

// The command used all 12 views, says how closely they fit, and wrote the lens.
void expectTwelveViewsGaveTheLens(const test::ShellResult& r, const std::filesystem::path& lens) {
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("intrinsics: 12 views of 12 frames searched;"), std::string::npos) << r.out;
    const double rms = printedRms(r.out);
    EXPECT_GT(rms, 0.0) << r.out;
    EXPECT_LT(rms, 1.0) << r.out;
    expectTheLens(lens);
}

}  // namespace

TEST(CalibrateIntrinsics, chessboardPhotosInAFolderGiveBackTheLens) {
    TempDir dir;
    writeChessboardPhotos(dir.path() / "views", 12);
    const auto lens = dir.path() / "lens.yaml";
    const auto r = calibrateIntrinsics((dir.path() / "views").string() +
                                       " --board chessboard --cols 9 --rows 6 --square 0.025 --out " + lens.string());
    expectTwelveViewsGaveTheLens(r, lens);
}

TEST(CalibrateIntrinsics, charucoVideoGivesBackTheLensFromEvenlySpreadFrames) {
    TempDir dir;
    const auto video = dir.path() / "board.avi";
    {
        // Each view twice in a row: 24 frames, of which --max-views 12 searches every other one.
        cv::VideoWriter writer(video.string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 10.0, kLens.size);
        ASSERT_TRUE(writer.isOpened());
        const cv::Mat board = charucoTexture(charucoBoard(), kTexels);
        for (const BoardPose& pose : kPoses) {
            const cv::Mat frame = photo(board, pose);
            writer.write(frame);
            writer.write(frame);
        }
    }
    const auto lens = dir.path() / "lens.yaml";
    const auto r = calibrateIntrinsics(video.string() +
                                       " --board charuco --cols 9 --rows 6 --square 0.025 --marker-length 0.018 " +
                                       "--max-views 12 --out " + lens.string());
    expectTwelveViewsGaveTheLens(r, lens);
}

// The lens file placed by a marker through the same distorting lens: the
// two commands meet in the file.
TEST(CalibrateIntrinsics, theLensFileIsWhatCalibrateFloorTakesAsItsIntrinsics) {
    TempDir dir;
    writeChessboardPhotos(dir.path() / "views", 12);
    const auto lens = dir.path() / "lens.yaml";
    const auto r = calibrateIntrinsics((dir.path() / "views").string() +
                                       " --board chessboard --cols 9 --rows 6 --square 0.025 --out " + lens.string());
    ASSERT_EQ(r.code, 0) << r.out;

    // 2.5 m up at the floor's origin's x, 45 degrees down; a 0.5 m marker at the origin.
    const double height = 2.5, tilt = 45.0, z = height / std::tan(tilt * CV_PI / 180.0);
    const cv::Mat floor =
        floorWithMarkers(cv::aruco::getPredefinedDictionary(cv::aruco::DICT_4X4_50), {{5, 0.0, 0.0}}, 0.5, 3.0, 400);
    const auto plate = dir.path() / "plate.png";
    ASSERT_TRUE(cv::imwrite(plate.string(),
                            camera().photograph(floor, 1.0 / 400, {-1.5, -1.5}, floorToCamera(0.0, height, z, tilt))));
    const auto out = dir.path() / "camera.yaml";
    const auto f = test::arcompCommand("calibrate floor " + plate.string() + " --intrinsics " + lens.string() +
                                       " --marker 5 --marker-size 0.5 --out " + out.string());
    ASSERT_EQ(f.code, 0) << f.out;
    const CalibratedCamera found = readCameraFile(out);
    EXPECT_NEAR(found.heightMetres(), height, 0.03 * height);
    EXPECT_NEAR(found.tiltDegrees(), tilt, 1.5);
    EXPECT_NEAR(found.intrinsics.distortion[0], readCameraFile(lens).intrinsics.distortion[0], 1e-9);
}

enum class Pictures { None, Blank, ThreeViews, FarBoard };

struct IntrinsicsInputCase {
    const char* name;
    Pictures pictures;  // in views/
    const char* args;   // after the input
    const char* expected;
};

class CalibrateIntrinsicsRefuses : public ::testing::TestWithParam<IntrinsicsInputCase> {};

TEST_P(CalibrateIntrinsicsRefuses, withExitTwoAndTheReason) {
    TempDir dir;
    const auto views = dir.path() / "views";
    switch (GetParam().pictures) {
    case Pictures::None: break;
    case Pictures::Blank:
        std::filesystem::create_directories(views);
        for (int i = 0; i < 6; ++i)
            cv::imwrite((views / ("blank" + std::to_string(i) + ".png")).string(),
                        cv::Mat(480, 640, CV_8UC3, cv::Scalar::all(128)));
        break;
    case Pictures::ThreeViews: writeChessboardPhotos(views, 3); break;
    case Pictures::FarBoard: writeChessboardPhotos(views, 6, 2.8); break;
    }
    const auto r =
        calibrateIntrinsics(views.string() + " " + GetParam().args + " --out " + (dir.path() / "lens.yaml").string());
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_EQ(r.out.rfind("arcomp calibrate intrinsics: ", 0), 0u) << r.out;
    EXPECT_NE(r.out.find(GetParam().expected), std::string::npos) << r.out;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "lens.yaml"));
}

INSTANTIATE_TEST_SUITE_P(
    BadInput, CalibrateIntrinsicsRefuses,
    ::testing::Values(
        IntrinsicsInputCase{
            "noBoardInAnyFrame", Pictures::Blank, "--board chessboard --cols 9 --rows 6 --square 0.025",
            "no chessboard of 9 x 6 squares (8 x 5 inner corners) found in any of its 6 frames searched"},
        IntrinsicsInputCase{"tooFewViews", Pictures::ThreeViews, "--board chessboard --cols 9 --rows 6 --square 0.025",
                            "the board is usable in 3 views of the 3 frames searched; the lens needs at least 5"},
        IntrinsicsInputCase{"boardTooSmall", Pictures::FarBoard, "--board chessboard --cols 9 --rows 6 --square 0.025",
                            "the board covers under 2% of the image in every view where it was found ("},
        IntrinsicsInputCase{"tooFewSquares", Pictures::None, "--board chessboard --cols 3 --rows 6 --square 0.025",
                            "--cols 3 --rows 6: a chessboard needs 4 to 100 squares each way"},
        IntrinsicsInputCase{"squareChessboard", Pictures::None, "--board chessboard --cols 7 --rows 7 --square 0.025",
                            "--cols and --rows are both 7"},
        IntrinsicsInputCase{"noSquareSize", Pictures::None, "--board chessboard --cols 9 --rows 6 --square 0",
                            "--square 0: a square's edge must be a positive length in metres"},
        IntrinsicsInputCase{"charucoWithoutMarkers", Pictures::None, "--board charuco --cols 9 --rows 6 --square 0.025",
                            "--marker-length 0: a ChArUco board needs its markers' edge in metres"},
        IntrinsicsInputCase{"charucoTooBigForItsDictionary", Pictures::None,
                            "--board charuco --cols 12 --rows 10 --square 0.025 --marker-length 0.018",
                            "--dictionary DICT_4X4_50: has 50 markers, and a 12 x 10 ChArUco board needs 60"},
        IntrinsicsInputCase{"unknownBoard", Pictures::None, "--board circles --cols 9 --rows 6 --square 0.025",
                            "--board circles: expected chessboard or charuco"},
        IntrinsicsInputCase{"missingInput", Pictures::None, "--board chessboard --cols 9 --rows 6 --square 0.025",
                            "/views: no such file, folder or camera"}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace arcomp
