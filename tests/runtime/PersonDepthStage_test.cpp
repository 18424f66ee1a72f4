// Who stood where this frame, as the calibration overlay shows it: each
// person's foot point in frame pixels (also when tracking runs at a
// reduced size), the distance their feet give, and whether that distance was
// measured now, kept from an earlier frame, or is the person plane's.

#include "runtime/station/PersonDepthStage.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace arcomp;

namespace {

// 3 m up, looking along -z and 18 degrees down, calibrated at `size`.
CalibratedCamera camera(glm::ivec2 size) {
    CalibratedCamera c;
    const double s = size.x / 640.0;
    c.intrinsics = {
        .imageSize = size, .fx = 560.0 * s, .fy = 556.0 * s, .cx = 331.0 * s, .cy = 228.5 * s, .distortion = {}};
    const double tilt = glm::radians(18.0);
    const glm::dvec3 forward(0.0, -std::sin(tilt), -std::cos(tilt)), right(1.0, 0.0, 0.0);
    c.rotation = glm::transpose(glm::dmat3(right, glm::cross(forward, right), forward));
    c.translation = -c.rotation * glm::dvec3(-0.5, 3.0, 9.0);
    return c;
}

// A matte (premultiplied BGRA) with one opaque person card: rows top..bottom, columns left..right, inclusive.
cv::Mat matteWith(glm::ivec2 size, int left, int right, int top, int bottom) {
    cv::Mat person(size.y, size.x, CV_8UC4, cv::Scalar::all(0));
    person(cv::Range(top, bottom + 1), cv::Range(left, right + 1)).setTo(cv::Scalar::all(255));
    return person;
}

double depthAt(const CalibratedCamera& c, glm::dvec2 pixel) { return c.depthOf(*c.floorPointAt(pixel)); }

}  // namespace

TEST(PersonDepthStage, aPersonSeenWithTheirFeetIsMeasuredAtTheirFootPixel) {
    const CalibratedCamera c = camera({640, 480});
    PersonDepthStage stage(c, 5.0f, {640, 480});
    stage.run(matteWith({640, 480}, 280, 320, 250, 420), true);
    ASSERT_EQ(stage.standing().size(), 1u);
    const StandingPerson& p = stage.standing()[0];
    EXPECT_GE(p.id, 1);
    // Tracking runs at half size here: the foot is the centre of a 2x2 block, within a pixel.
    EXPECT_NEAR(p.foot.x, 300.0f, 1.0f);
    EXPECT_NEAR(p.foot.y, 420.0f, 1.0f);
    EXPECT_EQ(p.depth, StandingPerson::Depth::Measured);
    EXPECT_NEAR(p.metres, depthAt(c, glm::dvec2(p.foot)), 1e-3);
    EXPECT_FLOAT_EQ(stage.depths().metres[1], p.metres);  // the slot the compositor uses says the same
}

TEST(PersonDepthStage, feetOutOfThePictureKeepTheLastDistanceAndAnUnmeasuredPersonStandsOnThePlane) {
    const CalibratedCamera c = camera({640, 480});
    PersonDepthStage stage(c, 5.0f, {640, 480});
    stage.run(matteWith({640, 480}, 280, 320, 250, 420), true);
    const float measured = stage.standing().at(0).metres;
    // The same person walks towards the camera until the frame's bottom edge cuts their feet off.
    stage.run(matteWith({640, 480}, 282, 322, 280, 479), true);
    ASSERT_EQ(stage.standing().size(), 1u);
    EXPECT_EQ(stage.standing()[0].depth, StandingPerson::Depth::Kept);
    EXPECT_FLOAT_EQ(stage.standing()[0].metres, measured);

    // Someone never seen with their feet in the picture.
    PersonDepthStage fresh(c, 5.0f, {640, 480});
    fresh.run(matteWith({640, 480}, 100, 140, 300, 479), true);
    ASSERT_EQ(fresh.standing().size(), 1u);
    EXPECT_EQ(fresh.standing()[0].depth, StandingPerson::Depth::Plane);
    EXPECT_FLOAT_EQ(fresh.standing()[0].metres, 5.0f);
}

TEST(PersonDepthStage, footPointsAreInFramePixelsWhenTrackingRunsAtAQuarterSize) {
    const CalibratedCamera c = camera({1920, 1080});
    PersonDepthStage stage(c, 5.0f, {1920, 1080});
    ASSERT_EQ(stage.scale(), 4);
    stage.run(matteWith({1920, 1080}, 960, 1040, 700, 900), true);
    ASSERT_EQ(stage.standing().size(), 1u);
    // Tracking pixel (250, 225) covers frame pixels 1000..1003 and 900..903: its centre.
    EXPECT_NEAR(stage.standing()[0].foot.x, 1001.5f, 1e-4f);
    EXPECT_NEAR(stage.standing()[0].foot.y, 901.5f, 1e-4f);
}

TEST(PersonDepthStage, withoutACalibratedCameraPeopleAreTrackedButAllStandOnThePlane) {
    PersonDepthStage stage(std::nullopt, 5.0f, {640, 480});
    stage.run(matteWith({640, 480}, 280, 320, 250, 420), true);
    EXPECT_TRUE(stage.standing().empty());
    EXPECT_EQ(stage.depths().people, 0);
    EXPECT_FLOAT_EQ(stage.depths().metres[0], 5.0f);
    ASSERT_EQ(stage.people().size(), 1u);  // what the station publishes in the picture
    EXPECT_EQ(stage.people()[0].missed, 0);
}
