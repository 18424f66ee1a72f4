// The operator's panel: frames over the target are drawn in the warning
// colour, a lost camera's line turns to it too, and the panel is
// premultiplied (no channel above its alpha).

#include "runtime/app/StatsOverlay.hpp"

#include <gtest/gtest.h>

using namespace arcomp;

namespace {

// Pixels in the warning red (235, 70, 60), exactly as drawn (bars are not antialiased).
int warningPixels(const cv::Mat& rgba) {
    int n = 0;
    for (auto it = rgba.begin<cv::Vec4b>(); it != rgba.end<cv::Vec4b>(); ++it) n += *it == cv::Vec4b(235, 70, 60, 255);
    return n;
}

}  // namespace

TEST(StatsOverlay, framesOverTheTargetAreDrawnInTheWarningColour) {
    const CameraLine camera{"front", {SourceStatus::Streaming, ""}, 0};
    StatsOverlay onTime, late;
    for (int i = 0; i < 60; ++i) {
        onTime.add({}, {}, camera, 15.0, 16.7);
        late.add({}, {}, camera, i % 2 ? 15.0 : 40.0, 16.7);
    }
    EXPECT_EQ(warningPixels(onTime.image()), 0);
    EXPECT_GT(warningPixels(late.image()), 30 * 10);  // 30 bars, each at least 1 px wide and several high
}

TEST(StatsOverlay, lostCameraLineTurnsToTheWarningColour) {
    StatsOverlay streaming, lost;
    streaming.add({}, {}, {"front", {SourceStatus::Streaming, ""}, 0}, 10.0, 16.7);
    lost.add({}, {}, {"front", {SourceStatus::Disconnected, "/dev/video0: ENODEV"}, 12}, 10.0, 16.7);
    // Antialiased text: count pixels whose colour leans to the warning red.
    auto reddish = [](const cv::Mat& rgba) {
        int n = 0;
        for (auto it = rgba.begin<cv::Vec4b>(); it != rgba.end<cv::Vec4b>(); ++it)
            n += (*it)[0] > 120 && (*it)[1] < 60 + (*it)[0] / 4;
        return n;
    };
    EXPECT_EQ(reddish(streaming.image()), 0);
    EXPECT_GT(reddish(lost.image()), 50);
}

TEST(StatsOverlay, imageIsPremultiplied) {
    StatsOverlay overlay;
    FrameStats stats;
    stats.budget = BudgetStats{.targetMs = 16.7, .predictedMs = 15.0, .measuredMs = 17.0, .quality = 0.8};
    DrawList drawn;
    drawn.items.push_back(
        DrawItem{.node = 0, .part = {}, .viewDistance = 1, .screenArea = 1, .level = 1, .shading = Shading::Flat});
    overlay.add(stats, drawn, {"front", {SourceStatus::Stalled, "no frame for 2 s"}, 3}, 20.0, 16.7);
    const cv::Mat& rgba = overlay.image();
    ASSERT_EQ(rgba.type(), CV_8UC4);
    for (auto it = rgba.begin<cv::Vec4b>(); it != rgba.end<cv::Vec4b>(); ++it)
        ASSERT_TRUE((*it)[0] <= (*it)[3] && (*it)[1] <= (*it)[3] && (*it)[2] <= (*it)[3]);
}
