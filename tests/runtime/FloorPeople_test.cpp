// The tracker's people as visitors: a person whose near foot and head are
// imaged through a known camera stands where they were placed, as tall as
// they are; velocities are per second of video; enter and leave come at the
// frames an id first and last appears; without a calibration, positions are
// in the picture.

#include "runtime/people/FloorPeople.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace arcomp;

namespace {

constexpr glm::ivec2 kImageSize{640, 480};

// 3 m up at (-0.5, 9), looking along -z and 18 degrees down.
CalibratedCamera camera() {
    CalibratedCamera c;
    c.intrinsics = {.imageSize = kImageSize, .fx = 560.0, .fy = 556.0, .cx = 331.0, .cy = 228.5, .distortion = {}};
    const double tilt = glm::radians(18.0);
    const glm::dvec3 forward(0.0, -std::sin(tilt), -std::cos(tilt)), right(1.0, 0.0, 0.0);
    c.rotation = glm::transpose(glm::dmat3(right, glm::cross(forward, right), forward));
    c.translation = -c.rotation * glm::dvec3(-0.5, 3.0, 9.0);
    return c;
}

// A person 0.3 m deep and `height` tall, their middle at floor (x, z), seen
// by `c`: the tracker's foot point is their near side's bottom (0.15 m from
// the middle, along the floor towards the camera), the blob's top row their
// head above the middle.
TrackedPerson seenAt(const CalibratedCamera& c, int id, double x, double z, double height = 1.7) {
    const glm::dvec3 middle(x, 0.0, z);
    glm::dvec3 towardsLens = c.position() - middle;
    towardsLens.y = 0.0;
    const glm::dvec2 foot = c.project(middle + 0.15 * glm::normalize(towardsLens));
    const glm::dvec2 head = c.project({x, height, z});
    TrackedPerson t;
    t.id = id;
    t.foot = {static_cast<float>(foot.x), static_cast<float>(foot.y)};
    t.box = cv::Rect(static_cast<int>(std::lround(foot.x)) - 20, static_cast<int>(std::lround(head.y)), 40,
                     static_cast<int>(std::lround(foot.y - head.y)));
    t.feetVisible = true;
    return t;
}

}  // namespace

TEST(FloorPeople, aPersonStandsWhereTheirMiddleIsNotWhereTheirNearFootIs) {
    const CalibratedCamera c = camera();
    FloorPeople floor(c, kImageSize);
    const PeopleFrame& now = floor.update({seenAt(c, 4, 0.3, 2.0)}, 1, 0, 0.0, true);
    EXPECT_EQ(now.units, PositionUnits::FloorMetres);
    ASSERT_EQ(now.people.size(), 1u);
    const Person& p = now.people[0];
    EXPECT_EQ(p.id, 4);
    EXPECT_TRUE(p.seen);
    EXPECT_NEAR(p.position.x, 0.3f, 0.01f);
    EXPECT_NEAR(p.position.y, 2.0f, 0.01f);
    // The head's row is whole pixels: about 1.4 cm a pixel at this distance.
    EXPECT_NEAR(p.heightMetres, 1.7f, 0.03f);
    EXPECT_EQ(now.entered, std::vector<int>{4});
    EXPECT_TRUE(now.left.empty());
}

TEST(FloorPeople, velocityIsMetresPerSecondOfVideoTime) {
    const CalibratedCamera c = camera();
    FloorPeople floor(c, kImageSize);
    // 25 fps, walking towards +x at 1.5 m/s and towards the camera at 0.5 m/s.
    const PeopleFrame* now = nullptr;
    for (int i = 0; i < 40; ++i) {
        const double t = i / 25.0;
        now = &floor.update({seenAt(c, 1, -1.0 + 1.5 * t, 1.0 + 0.5 * t)}, 1, static_cast<std::uint64_t>(i), t, true);
    }
    ASSERT_EQ(now->people.size(), 1u);
    EXPECT_NEAR(now->people[0].velocity.x, 1.5f, 0.05f);
    EXPECT_NEAR(now->people[0].velocity.y, 0.5f, 0.05f);
    EXPECT_NEAR(now->people[0].ageSeconds, 39 / 25.0, 1e-9);
    EXPECT_EQ(now->frame, 39u);
}

TEST(FloorPeople, enterAndLeaveComeAtTheFramesAnIdFirstAndLastAppears) {
    const CalibratedCamera c = camera();
    FloorPeople floor(c, kImageSize);
    EXPECT_TRUE(floor.update({}, 1, 0, 0.0, true).people.empty());
    PeopleFrame f = floor.update({seenAt(c, 7, 0.0, 3.0)}, 1, 1, 0.04, true);
    EXPECT_EQ(f.entered, std::vector<int>{7});
    f = floor.update({seenAt(c, 7, 0.0, 3.0), seenAt(c, 8, 1.0, 1.0)}, 1, 2, 0.08, true);
    EXPECT_EQ(f.entered, std::vector<int>{8});
    ASSERT_EQ(f.people.size(), 2u);

    // 7 hidden: still followed, at its last place, not seen.
    TrackedPerson hidden = seenAt(c, 7, 0.5, 3.0);
    hidden.missed = 1;
    f = floor.update({hidden, seenAt(c, 8, 1.0, 1.0)}, 1, 3, 0.12, true);
    EXPECT_TRUE(f.entered.empty());
    EXPECT_TRUE(f.left.empty());
    ASSERT_EQ(f.people.size(), 2u);
    EXPECT_EQ(f.people[0].id, 7);
    EXPECT_FALSE(f.people[0].seen);
    EXPECT_NEAR(f.people[0].position.x, 0.0f, 0.01f);

    // The tracker gives 7 up.
    f = floor.update({seenAt(c, 8, 1.0, 1.0)}, 1, 4, 0.16, true);
    EXPECT_EQ(f.left, std::vector<int>{7});
    ASSERT_EQ(f.people.size(), 1u);
    f = floor.update({}, 1, 5, 0.20, true);
    EXPECT_EQ(f.left, std::vector<int>{8});
    EXPECT_TRUE(f.people.empty());
}

TEST(FloorPeople, aPersonWhoseFeetWereNeverInThePictureIsNotPublished) {
    const CalibratedCamera c = camera();
    FloorPeople floor(c, kImageSize);
    TrackedPerson cut = seenAt(c, 3, 0.0, 7.0);
    cut.feetVisible = false;
    EXPECT_TRUE(floor.update({cut}, 1, 0, 0.0, true).people.empty());
    const PeopleFrame& f = floor.update({seenAt(c, 3, 0.0, 7.0)}, 1, 1, 0.04, true);
    EXPECT_EQ(f.entered, std::vector<int>{3});
    EXPECT_DOUBLE_EQ(f.people.at(0).ageSeconds, 0.0);  // enters when first placed, not when first tracked
}

TEST(FloorPeople, withoutACalibrationPositionsAreTheFootPointInThePicture) {
    FloorPeople floor(std::nullopt, kImageSize);
    TrackedPerson t;
    t.id = 2;
    t.foot = {80.0f, 60.0f};  // tracking pixels at half size
    t.box = cv::Rect(70, 20, 20, 40);
    t.feetVisible = true;
    const PeopleFrame& f = floor.update({t}, 2, 0, 0.0, true);
    EXPECT_EQ(f.units, PositionUnits::ImageNormalised);
    EXPECT_STREQ(unitsName(f.units), "image");
    ASSERT_EQ(f.people.size(), 1u);
    // Tracking pixel 80 is frame pixels 160..161: their centre, 160.5.
    EXPECT_FLOAT_EQ(f.people[0].position.x, 160.5f / 640.0f);
    EXPECT_FLOAT_EQ(f.people[0].position.y, 120.5f / 480.0f);
    EXPECT_EQ(f.people[0].box, (PixelBox{140, 40, 40, 80}));
    EXPECT_EQ(f.people[0].heightMetres, 0.0f);
}

TEST(FloorPeople, aFrameWhoseVideoDidNotChangeKeepsThePeopleAndOnlyAgesThem) {
    const CalibratedCamera c = camera();
    FloorPeople floor(c, kImageSize);
    const PeopleFrame first = floor.update({seenAt(c, 5, 0.0, 2.0)}, 1, 0, 1.0, true);
    const PeopleFrame& again = floor.update({}, 1, 1, 1.5, false);
    EXPECT_TRUE(again.entered.empty());
    EXPECT_TRUE(again.left.empty());
    ASSERT_EQ(again.people.size(), 1u);
    EXPECT_EQ(again.people[0].position, first.people[0].position);
    EXPECT_DOUBLE_EQ(again.people[0].ageSeconds, 0.5);
    EXPECT_EQ(again.frame, 1u);
}
