#include "video/matte/ConsensusMatte.hpp"

#include "tools/bench/report/MatteScore.hpp"
#include "tools/bench/scenes/CdnetSequence.hpp"
#include "video/matte/BackgroundMatte.hpp"

#include "video/pixels/VideoError.hpp"

#include "tests/support/MaskOverlap.hpp"
#include "tests/support/TempDir.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <filesystem>

namespace arcomp {
namespace {

constexpr double kFps = 10.0;

// A synthetic place at 10 fps: a static textured floor (blurred colour
// noise) with sensor noise on every frame, and textured figures (a
// red-brown ellipse with its own pattern) that the test moves or holds.
class Place {
public:
    Place(int w, int h) {
        floor_.create(h, w, CV_8UC3);
        cv::randu(floor_, cv::Scalar::all(40), cv::Scalar::all(220));
        cv::GaussianBlur(floor_, floor_, {9, 9}, 0.0);
        clothes_.create(h, w, CV_8UC3);
        cv::randu(clothes_, cv::Scalar(20, 40, 140), cv::Scalar(60, 80, 200));
    }
    cv::Size size() const { return floor_.size(); }

    struct Figure {
        cv::Point centre;
        double shadowDarkening = 0.0;  // > 0: a cast shadow on the floor to the figure's right, this dark
    };

    // The frame with `figures`; `truth` gets the figures' pixels (255),
    // `shadow` the shadows' pixels not covered by a figure.
    cv::Mat frame(const std::vector<Figure>& figures, cv::Mat* truth = nullptr, cv::Mat* shadow = nullptr,
                  double gain = 1.0) {
        cv::Mat f = floor_.clone();
        cv::Mat people = cv::Mat::zeros(f.size(), CV_8UC1), shadows = people.clone();
        for (const Figure& g : figures) {
            cv::ellipse(people, g.centre, axes(), 0.0, 0.0, 360.0, 255, cv::FILLED);
            if (g.shadowDarkening > 0.0) {
                // The shadow falls on the floor from the feet, long and flat.
                const cv::Point feet(g.centre.x, g.centre.y + axes().height);
                cv::ellipse(shadows, feet + cv::Point(axes().height, -4), {axes().height, axes().width / 2}, 0.0, 0.0,
                            360.0, 255, cv::FILLED);
                cv::Mat dark;
                f.convertTo(dark, -1, 1.0 - g.shadowDarkening);
                dark.copyTo(f, shadows);
            }
        }
        clothes_.copyTo(f, people);
        shadows.setTo(0, people);
        if (gain != 1.0) f.convertTo(f, -1, gain);
        cv::Mat noise(f.size(), CV_16SC3), f16;
        cv::randn(noise, cv::Scalar::all(0), cv::Scalar::all(2));
        f.convertTo(f16, CV_16SC3);
        f16 += noise;
        f16.convertTo(f, CV_8UC3);
        if (truth) *truth = people;
        if (shadow) *shadow = shadows;
        return f;
    }
    cv::Mat empty(double gain = 1.0) { return frame({}, nullptr, nullptr, gain); }

private:
    cv::Size axes() const { return {floor_.cols / 14, floor_.rows / 4}; }
    cv::Mat floor_, clothes_;
};

BackgroundSpec spec() {
    BackgroundSpec s;
    s.consensus.fps = kFps;
    return s;
}

cv::Mat found(const cv::Mat& person) { return alphaOf(person) > 127; }

// Pixels matted that are no person: the matte's false alarms.
int falseAlarms(const cv::Mat& matted, const cv::Mat& truth) { return cv::countNonZero(matted & ~truth); }

TEST(ConsensusMatte, isTheDefaultBackgroundMethod) {
    EXPECT_EQ(BackgroundSpec{}.method, BackgroundMethod::Consensus);
    MatteSpec matte;
    matte.kind = MatteKind::Background;
    EXPECT_EQ(makeMatte(matte)->name(), "background consensus");
}

TEST(ConsensusMatte, emptyPlaceGivesNoPerson) {
    Place place(320, 240);
    ConsensusMatte matte(spec());
    cv::Mat person;
    for (int i = 0; i < 60; ++i) matte.apply(place.empty(), person);
    EXPECT_EQ(cv::countNonZero(found(person)), 0);
}

TEST(ConsensusMatte, stillPersonIsStillMattedAfterSixtySeconds) {
    Place place(320, 240);
    ConsensusMatte matte(spec());
    cv::Mat person, truth;
    for (int i = 0; i < 30; ++i) matte.apply(place.empty(), person);
    // Walks in from the left, then stands still for 60 s.
    for (int x = 20; x < 160; x += 10) matte.apply(place.frame({{{x, 120}}}), person);
    const int stillFrames = static_cast<int>(60 * kFps);
    for (int i = 0; i < stillFrames; ++i) matte.apply(place.frame({{{160, 120}}}, &truth), person);
    EXPECT_GE(arcomp::test::maskIou(found(person), truth), 0.9);
}

TEST(ConsensusMatte, busStationsStandingPersonStaysMatted) {
    // Real footage: from about frame 450 a man stands at the door, and from
    // about 850 talks with a second; frames 700..900 are 10-18 s into his stay.
    const std::filesystem::path dir = std::filesystem::path(ARCOMP_SHARED_DATA) / "video/busStation";
    if (!std::filesystem::exists(dir)) GTEST_SKIP() << dir << " absent";
    const CdnetSequence seq = openCdnetSequence(dir);
    BackgroundSpec s;
    s.consensus.fps = 25.0;
    ConsensusMatte consensus(s);
    BackgroundMatte mog2({.method = BackgroundMethod::Mog2});  // the station's default before
    MatteScore standing, standingMog2;
    cv::Mat person, person2;
    for (int i = 1; i <= 900; ++i) {
        const cv::Mat frame = seq.frame(i);
        consensus.apply(frame, person);
        mog2.apply(frame, person2);
        if (i < 700) continue;
        const cv::Mat labels = seq.labels(i);
        standing.add(found(person), labels, seq.roi);
        standingMog2.add(found(person2), labels, seq.roi);
    }
    EXPECT_GE(standing.recall(), 0.65);
    EXPECT_GE(standing.precision(), 0.9);
    EXPECT_GT(standing.recall(), 2.0 * standingMog2.recall()) << "MOG2 learns him into the background";
}

TEST(ConsensusMatte, somethingLeftBehindJoinsTheBackgroundInTheEnd) {
    Place place(160, 120);
    BackgroundSpec s = spec();
    s.consensus.absorbSeconds = 20.0;
    ConsensusMatte matte(s);
    cv::Mat person, truth;
    for (int i = 0; i < 30; ++i) matte.apply(place.empty(), person);
    for (int i = 0; i < 10 * kFps; ++i) matte.apply(place.frame({{{80, 60}}}, &truth), person);
    EXPECT_GE(arcomp::test::maskIou(found(person), truth), 0.9) << "still matted before absorb_s";
    for (int i = 0; i < 60 * kFps; ++i) matte.apply(place.frame({{{80, 60}}}), person);
    EXPECT_LT(cv::countNonZero(found(person)), cv::countNonZero(truth) / 10) << "learnt well after absorb_s";
}

TEST(ConsensusMatte, castShadowIsNotMattedButThePersonIs) {
    Place place(320, 240);
    ConsensusMatte matte(spec());
    cv::Mat person, truth, shadow;
    for (int i = 0; i < 30; ++i) matte.apply(place.empty(), person);
    for (double darkening : {0.3, 0.5}) {  // a soft and a hard shadow
        for (int x = 40; x < 200; x += 12) matte.apply(place.frame({{{x, 110}, darkening}}, &truth, &shadow), person);
        ASSERT_GT(cv::countNonZero(shadow), 500);
        const cv::Mat matted = found(person);
        EXPECT_LT(cv::countNonZero(matted & shadow), cv::countNonZero(shadow) / 20) << "darkening " << darkening;
        EXPECT_GE(arcomp::test::maskIou(matted, truth), 0.85) << "darkening " << darkening;
    }
}

TEST(ConsensusMatte, globalLightChangeFloodsAtMostAFewFrames) {
    Place place(320, 240);
    ConsensusMatte matte(spec());
    cv::Mat person, truth;
    for (int i = 0; i < 30; ++i) matte.apply(place.empty(), person);
    for (int x = 40; x < 100; x += 12) matte.apply(place.frame({{{x, 120}}}), person);
    // Auto-exposure opens up by 40 % at once, while the person is in view.
    int flooded = 0;
    for (int x = 100; x < 220; x += 12) {
        matte.apply(place.frame({{{x, 120}}}, &truth, nullptr, 1.4), person);
        if (falseAlarms(found(person), truth) > cv::countNonZero(truth) / 4) ++flooded;
    }
    EXPECT_LE(flooded, 3);
    EXPECT_GE(matte.model().lightChanges(), 1) << "corrected as a light change, not learnt pixel by pixel";
    EXPECT_GE(arcomp::test::maskIou(found(person), truth), 0.85);
}

TEST(ConsensusMatte, busySceneStartNeedsNoEmptyFrame) {
    Place place(320, 240);
    ConsensusMatte matte(spec());
    cv::Mat person, truth;
    // Two people cross the place from the very first frame, in opposite directions.
    for (int i = 0; i < 40; ++i) {
        const int x = (20 + 9 * i) % 320;
        matte.apply(place.frame({{{x, 80}}, {{300 - x, 170}}}, &truth), person);
    }
    const cv::Mat matted = found(person);
    EXPECT_GE(arcomp::test::maskIou(matted, truth), 0.85);
    EXPECT_LT(falseAlarms(matted, truth), 320 * 240 / 200) << "no ghosts where they walked during the warm-up";
}

TEST(ConsensusMatte, someoneStandingThroughTheStartLeavesNoGhost) {
    Place place(320, 240);
    ConsensusMatte matte(spec());
    cv::Mat person, truth, standing;
    // In view and still for the whole warm-up median (3 s), then walks off to the right.
    for (int i = 0; i < 30; ++i) matte.apply(place.frame({{{100, 120}}}, &standing), person);
    for (int x = 100; x < 380; x += 14) matte.apply(place.frame({{{x, 120}}}), person);
    // Two seconds of the empty place.
    for (int i = 0; i < 20; ++i) matte.apply(place.empty(), person);
    EXPECT_LT(cv::countNonZero(found(person) & standing), cv::countNonZero(standing) / 20)
        << "the place they left is background again well before absorb_s";
    // And a person who then comes to stand there is matted.
    for (int x = 20; x <= 100; x += 10) matte.apply(place.frame({{{x, 120}}}, &truth), person);
    for (int i = 0; i < 50; ++i) matte.apply(place.frame({{{100, 120}}}, &truth), person);
    EXPECT_GE(arcomp::test::maskIou(found(person), truth), 0.9);
}

TEST(ConsensusMatte, cleanPlateStartsTheModelAtOnce) {
    Place place(320, 240);
    const arcomp::test::TempDir tmp;
    const std::string file = (tmp.path() / "consensus-plate.png").string();
    ASSERT_TRUE(cv::imwrite(file, place.empty()));
    BackgroundSpec s = spec();
    s.cleanPlate = file;
    ConsensusMatte matte(s);
    cv::Mat person, truth;
    // A person standing in view from the first frame: only the plate can tell.
    for (int i = 0; i < 40; ++i) matte.apply(place.frame({{{160, 120}}}, &truth), person);
    EXPECT_GE(arcomp::test::maskIou(found(person), truth), 0.9);
}

TEST(ConsensusMatte, edgeFollowsTheImageAtFullSize) {
    // A coarse model (a quarter of the size): the outline at full size comes
    // from the guided edge, which must beat plainly scaling the mask up.
    const auto outlineIou = [](int edgeRadiusPx) {
        Place place(320, 240);
        BackgroundSpec s = spec();
        s.scale = 0.25;
        s.consensus.edgeRadiusPx = edgeRadiusPx;
        ConsensusMatte matte(s);
        cv::Mat person, truth;
        for (int i = 0; i < 30; ++i) matte.apply(place.empty(), person);
        for (int x = 40; x < 200; x += 12) matte.apply(place.frame({{{x, 120}}}, &truth), person);
        return arcomp::test::maskIou(found(person), truth);
    };
    const double guided = outlineIou(BackgroundSpec{}.consensus.edgeRadiusPx), scaledUp = outlineIou(0);
    EXPECT_GT(guided, scaledUp);
    EXPECT_GE(guided, 0.85);
}

TEST(ConsensusMatte, badSettingsAndAMissingPlateAreRefused) {
    BackgroundSpec s = spec();
    s.consensus.matches = 50;
    EXPECT_THROW(ConsensusMatte{s}, VideoError);
    s = spec();
    s.consensus.shadowDarkest = 0.95;
    EXPECT_THROW(ConsensusMatte{s}, VideoError);
    s = spec();
    s.cleanPlate = "/nonexistent/plate.png";
    try {
        ConsensusMatte matte(s);
        FAIL() << "accepted a missing plate";
    } catch (const VideoError& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/plate.png"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace arcomp
