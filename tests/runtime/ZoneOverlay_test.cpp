// The zone overlay: each zone's outline where it lies in the picture, in
// one colour when empty and another when someone stands in it, over the
// overlay below it; a floor zone is drawn only through a calibrated camera.

#include "runtime/app/ZoneOverlay.hpp"

#include <gtest/gtest.h>

using namespace arcomp;

namespace {

const Zone kDoor{.name = "door",
                 .space = ZoneSpace::Image,
                 .polygon = {{0.25f, 0.25f}, {0.75f, 0.25f}, {0.75f, 0.75f}, {0.25f, 0.75f}},
                 .center = {},
                 .radius = 0.0f,
                 .enterMargin = 0.02f,
                 .leaveMargin = 0.02f};

cv::Vec4b at(const cv::Mat& image, int x, int y) { return image.at<cv::Vec4b>(y, x); }

}  // namespace

TEST(ZoneOverlay, drawsAPictureZonesOutlineInTheColourOfItsOccupancy) {
    ZoneOverlay overlay;
    const std::vector<Zone> zones{kDoor};
    overlay.draw(nullptr, zones, std::vector<ZoneCount>{{.name = "door", .people = 0, .entries = 0}}, std::nullopt,
                 {200, 100});
    ASSERT_EQ(overlay.image().size(), cv::Size(200, 100));
    const cv::Vec4b empty = at(overlay.image(), 50, 50);  // on the left edge
    EXPECT_GT(empty[3], 0);
    EXPECT_GT(empty[0], empty[1]) << "an empty zone is amber";
    EXPECT_EQ(at(overlay.image(), 100, 50)[3], 0) << "inside is left clear";

    overlay.draw(nullptr, zones, std::vector<ZoneCount>{{.name = "door", .people = 2, .entries = 3}}, std::nullopt,
                 {200, 100});
    const cv::Vec4b occupied = at(overlay.image(), 50, 50);
    EXPECT_GT(occupied[1], occupied[0]) << "an occupied zone is green";
}

TEST(ZoneOverlay, drawsOverTheOverlayBelowAndSkipsFloorZonesWithoutACamera) {
    cv::Mat below(100, 200, CV_8UC4, cv::Scalar(1, 2, 3, 4));
    const Zone floor{.name = "front",
                     .space = ZoneSpace::Floor,
                     .polygon = {},
                     .center = {0.0f, 2.0f},
                     .radius = 1.0f,
                     .enterMargin = 0.15f,
                     .leaveMargin = 0.15f};
    ZoneOverlay overlay;
    const std::vector<Zone> zones{floor};
    overlay.draw(&below, zones, std::vector<ZoneCount>{{.name = "front", .people = 1, .entries = 1}}, std::nullopt,
                 {200, 100});
    EXPECT_EQ(cv::norm(overlay.image(), below, cv::NORM_INF), 0.0) << "nothing to draw a floor zone through";
}
