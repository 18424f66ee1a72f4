// The calibration drawn over the video: grid lines cross exactly where the
// calibrated camera sees whole-metre floor points, nothing is drawn above the
// horizon (floor behind the lens is not folded into the sky), and each
// person's marker and label sit at their foot pixel.

#include "runtime/app/CalibrationOverlay.hpp"
#include "runtime/station/ImageFile.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace arcomp;

namespace {

// The camera of Station_test's calibrated station: 3 m up at (-0.5, 3, 9),
// looking along -z, tilted down by `tiltDegrees`.
CalibratedCamera cameraTilted(double tiltDegrees, glm::dvec3 eye = {-0.5, 3.0, 9.0}) {
    CalibratedCamera c;
    c.intrinsics = {.imageSize = {640, 480}, .fx = 560.0, .fy = 556.0, .cx = 331.0, .cy = 228.5, .distortion = {}};
    const double tilt = glm::radians(tiltDegrees);
    const glm::dvec3 forward(0.0, -std::sin(tilt), -std::cos(tilt)), right(1.0, 0.0, 0.0);
    c.rotation = glm::transpose(glm::dmat3(right, glm::cross(forward, right), forward));
    c.translation = -c.rotation * eye;
    return c;
}

// The most opaque pixel within `radius` of `pixel` (pixel centres at integers).
int alphaNear(const cv::Mat& rgba, glm::dvec2 pixel, int radius) {
    int most = 0;
    const int u = static_cast<int>(std::lround(pixel.x)), v = static_cast<int>(std::lround(pixel.y));
    for (int y = std::max(0, v - radius); y <= std::min(rgba.rows - 1, v + radius); ++y)
        for (int x = std::max(0, u - radius); x <= std::min(rgba.cols - 1, u + radius); ++x)
            most = std::max<int>(most, rgba.at<cv::Vec4b>(y, x)[3]);
    return most;
}

// For a person to look at when a test fails: the overlay over mid grey.
void writeOnFailure(const cv::Mat& rgba, const std::string& name) {
    if (!::testing::Test::HasFailure()) return;
    Image image{rgba.cols, rgba.rows, {}};
    image.rgba.reserve(rgba.total() * 4);
    for (auto it = rgba.begin<cv::Vec4b>(); it != rgba.end<cv::Vec4b>(); ++it)
        for (int c = 0; c < 4; ++c)
            image.rgba.push_back(static_cast<std::uint8_t>(c == 3 ? 255 : (*it)[c] + 128 * (255 - (*it)[3]) / 255));
    writePng(std::string(ARCOMP_TEST_OUTPUT) + "/calibration-overlay-" + name + ".png", image);
}

}  // namespace

TEST(CalibrationOverlay, gridLinesCrossWhereTheCameraSeesWholeMetreFloorPoints) {
    const CalibratedCamera camera = cameraTilted(18.0);
    CalibrationOverlay overlay;
    overlay.draw(camera, {640, 480}, {});
    const cv::Mat& image = overlay.image();
    ASSERT_EQ(image.type(), CV_8UC4);
    ASSERT_EQ(image.size(), cv::Size(640, 480));
    // (0, 0, 4.5) is 4.5 m in front of the point below the lens, low in the
    // picture, and on one line only (x = 0): that line runs on to z = 10,
    // behind the lens, and only that stretch may be left out, not the whole line.
    for (const glm::dvec3 floor :
         {glm::dvec3(0, 0, 0), glm::dvec3(2, 0, -3), glm::dvec3(-3, 0, 4), glm::dvec3(0, 0, 4.5)}) {
        const glm::dvec2 pixel = camera.project(floor);
        ASSERT_TRUE(pixel.x >= 0 && pixel.x < 640 && pixel.y >= 0 && pixel.y < 480) << floor.x << ", " << floor.z;
        EXPECT_GT(alphaNear(image, pixel, 1), 60) << "no grid at floor point " << floor.x << ", " << floor.z;
    }
    // Cell centres stay clear: the lines are where the metres are, not half a metre off.
    for (const glm::dvec3 floor : {glm::dvec3(1.5, 0, -2.5), glm::dvec3(-2.5, 0, 3.5)})
        EXPECT_EQ(alphaNear(image, camera.project(floor), 2), 0)
            << "grid in the cell at " << floor.x << ", " << floor.z;
    writeOnFailure(image, "grid");
}

TEST(CalibrationOverlay, nothingIsDrawnAboveTheHorizon) {
    // Steep and nearly level: the level one's grid reaches 20 m out, close to the horizon.
    for (const double tilt : {18.0, 2.0}) {
        const CalibratedCamera camera = cameraTilted(tilt);
        CalibrationOverlay overlay;
        overlay.draw(camera, {640, 480}, {});
        const cv::Mat& image = overlay.image();
        const double horizon = camera.intrinsics.cy - camera.intrinsics.fy * std::tan(glm::radians(tilt));
        int above = 0, below = 0;
        for (int y = 0; y < image.rows; ++y)
            for (int x = 0; x < image.cols; ++x)
                (y < horizon - 1.0 ? above : below) += image.at<cv::Vec4b>(y, x)[3] > 0;
        EXPECT_EQ(above, 0) << "tilt " << tilt << ": horizon at row " << horizon;
        EXPECT_GT(below, 1000) << "tilt " << tilt;
        writeOnFailure(image, "horizon");
    }
}

TEST(CalibrationOverlay, gridIsScaledToTheVideoSize) {
    const CalibratedCamera camera = cameraTilted(18.0);  // calibrated at 640x480
    CalibrationOverlay overlay;
    overlay.draw(camera, {320, 240}, {});
    ASSERT_EQ(overlay.image().size(), cv::Size(320, 240));
    for (const glm::dvec3 floor : {glm::dvec3(0, 0, 0), glm::dvec3(2, 0, -3)}) {
        const glm::dvec2 full = camera.project(floor);
        EXPECT_GT(alphaNear(overlay.image(), (full + 0.5) / 2.0 - 0.5, 1), 60) << floor.x << ", " << floor.z;
    }
}

TEST(CalibrationOverlay, aReloadedCameraMovesTheGrid) {
    const CalibratedCamera before = cameraTilted(18.0), after = cameraTilted(18.0, {0.0, 2.5, 8.0});
    CalibrationOverlay reused, fresh;
    reused.draw(before, {640, 480}, {});
    reused.draw(after, {640, 480}, {});
    fresh.draw(after, {640, 480}, {});
    EXPECT_EQ(cv::norm(reused.image(), fresh.image(), cv::NORM_INF), 0.0);
}

TEST(CalibrationOverlay, aPersonIsMarkedAndLabelledAtTheirFootPixel) {
    const CalibratedCamera camera = cameraTilted(18.0);
    CalibrationOverlay empty, marked;
    empty.draw(camera, {640, 480}, {});
    const StandingPerson person{
        .id = 3, .foot = {200.0f, 400.0f}, .metres = 7.4f, .depth = StandingPerson::Depth::Measured};
    marked.draw(camera, {640, 480}, {&person, 1});

    // The marker's centre dot is opaque and green (measured) at the foot.
    const cv::Vec4b centre = marked.image().at<cv::Vec4b>(400, 200);
    EXPECT_EQ(centre[3], 255);
    EXPECT_GT(centre[1], 200);
    EXPECT_LT(centre[0], 120);
    // Everything the person added lies in the marker and the label to its
    // right, on the foot's row.
    cv::Mat changed;
    cv::compare(marked.image().reshape(1), empty.image().reshape(1), changed, cv::CMP_NE);
    changed = changed.reshape(4);
    cv::Rect added;
    int labelPixels = 0;
    for (int y = 0; y < 480; ++y)
        for (int x = 0; x < 640; ++x)
            if (changed.at<cv::Vec4b>(y, x) != cv::Vec4b::all(0)) {
                added |= cv::Rect(x, y, 1, 1);
                labelPixels += x > 212;
            }
    EXPECT_GE(added.x, 190);
    EXPECT_LE(added.x, 193);  // the marker's ring: radius 7, 4 px thick outline
    EXPECT_GE(added.y, 388);
    EXPECT_LE(added.br().y, 412);
    EXPECT_GT(added.br().x, 260);  // "#3 7.4 m" at half scale is about 70 px long
    EXPECT_LT(added.br().x, 300);
    EXPECT_GT(labelPixels, 100);
    writeOnFailure(marked.image(), "person");
}

TEST(CalibrationOverlay, nearTheRightEdgeTheLabelIsOnTheMarkersLeft) {
    const CalibratedCamera camera = cameraTilted(18.0);
    CalibrationOverlay empty, marked;
    empty.draw(camera, {640, 480}, {});
    const StandingPerson person{
        .id = 6, .foot = {620.0f, 400.0f}, .metres = 11.2f, .depth = StandingPerson::Depth::Measured};
    marked.draw(camera, {640, 480}, {&person, 1});
    int leftOfMarker = 0;
    for (int y = 380; y < 420; ++y)
        for (int x = 0; x < 640; ++x)
            leftOfMarker += x < 608 && marked.image().at<cv::Vec4b>(y, x) != empty.image().at<cv::Vec4b>(y, x);
    EXPECT_GT(leftOfMarker, 100);
    writeOnFailure(marked.image(), "right-edge");
}

TEST(CalibrationOverlay, labelSaysWhereTheDistanceCameFrom) {
    EXPECT_EQ(standingLabel({.id = 3, .foot = {}, .metres = 7.43f, .depth = StandingPerson::Depth::Measured}),
              "#3 7.4 m");
    EXPECT_EQ(standingLabel({.id = 12, .foot = {}, .metres = 3.0f, .depth = StandingPerson::Depth::Kept}),
              "#12 3.0 m (kept)");
    EXPECT_EQ(standingLabel({.id = 1, .foot = {}, .metres = 5.0f, .depth = StandingPerson::Depth::Plane}),
              "#1 5.0 m (plane)");
}

TEST(CalibrationOverlay, imageIsPremultiplied) {
    const CalibratedCamera camera = cameraTilted(18.0);
    const StandingPerson people[] = {
        {.id = 1, .foot = {320.0f, 300.0f}, .metres = 9.0f, .depth = StandingPerson::Depth::Measured},
        {.id = 2, .foot = {330.0f, 310.0f}, .metres = 8.0f, .depth = StandingPerson::Depth::Kept},
        {.id = 4, .foot = {630.0f, 470.0f}, .metres = 5.0f, .depth = StandingPerson::Depth::Plane}};
    CalibrationOverlay overlay;
    overlay.draw(camera, {640, 480}, people);
    const cv::Mat& rgba = overlay.image();
    for (auto it = rgba.begin<cv::Vec4b>(); it != rgba.end<cv::Vec4b>(); ++it)
        ASSERT_TRUE((*it)[0] <= (*it)[3] && (*it)[1] <= (*it)[3] && (*it)[2] <= (*it)[3]);
}
