#include "runtime/station/GazeSource.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using namespace arcomp;

namespace {

std::string errorOf(std::string_view text) {
    try {
        parseGazeTrackCsv(text, "track.csv");
    } catch (const GazeTrackError& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace

TEST(GazeSource, fixedGazeIsNormalised) {
    FixedGaze g({0, 1, 0}, {0, 0, -5});
    const auto s = g.sample(2.0);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->direction, glm::vec3(0, 0, -1));
    EXPECT_EQ(s->eye, glm::vec3(0, 1, 0));
}

TEST(GazeSource, headPoseLooksAlongItsMinusZ) {
    HeadPoseGaze head;
    EXPECT_FALSE(head.sample(0.0));  // no pose yet
    const glm::mat4 pose = glm::rotate(glm::translate(glm::mat4(1.0f), {1, 2, 3}), glm::radians(90.0f), {0, 1, 0});
    head.setPose(pose);
    const auto s = head.sample(0.0);
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->direction.x, -1.0f, 1e-6f);  // turned left by 90°
    EXPECT_NEAR(s->direction.z, 0.0f, 1e-6f);
    EXPECT_EQ(s->eye, glm::vec3(1, 2, 3));
}

TEST(GazeSource, trackerSamplesArePlacedInWorld) {
    TrackerGaze tracker(
        [] {
            return std::optional<GazeSample>(GazeSample{0.0, {0, 0, 0}, {0, 0, -1}});
        },
        glm::translate(glm::mat4(1.0f), {0, 1.5f, 0}));
    const auto s = tracker.sample(1.0);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->eye, glm::vec3(0, 1.5f, 0));
    TrackerGaze lost([] { return std::optional<GazeSample>(); }, glm::mat4(1.0f));
    EXPECT_FALSE(lost.sample(1.0));
}

TEST(GazeSource, recordedTrackInterpolatesAndHoldsEnds) {
    RecordedGaze track(parseGazeTrackCsv("time,eye_x,eye_y,eye_z,gaze_x,gaze_y,gaze_z\n"
                                         "# a comment\n"
                                         "0.0, 0,0,0, 1,0,0\r\n"
                                         "\n"
                                         "1.0, 2,0,0, 0,0,3\n",
                                         "track.csv"));
    ASSERT_EQ(track.samples().size(), 2u);
    EXPECT_EQ(track.samples()[1].direction, glm::vec3(0, 0, 1));
    const auto mid = track.sample(0.5);
    EXPECT_NEAR(mid->eye.x, 1.0f, 1e-6f);
    EXPECT_NEAR(mid->direction.x, std::sqrt(0.5f), 1e-6f);
    EXPECT_NEAR(mid->direction.z, std::sqrt(0.5f), 1e-6f);
    EXPECT_EQ(track.sample(-1.0)->direction, glm::vec3(1, 0, 0));
    EXPECT_EQ(track.sample(9.0)->eye, glm::vec3(2, 0, 0));
}

TEST(GazeSource, trackErrorsNameFileAndLine) {
    EXPECT_EQ(errorOf("0,0,0,0,1,0,0\n1,0,0,0,1,0\n"),
              "track.csv:2: expected 7 comma-separated fields (time, eye xyz, gaze xyz), found 6");
    EXPECT_EQ(errorOf("0,0,0,0,1,0,0,9\n"), "track.csv:1: expected 7 fields, found more");
    EXPECT_EQ(errorOf("# c\n0,0,x,0,1,0,0\n"), "track.csv:2: eye_y: \"x\" is not a number");
    EXPECT_EQ(errorOf("0,0,0,0,0,0,0\n"), "track.csv:1: gaze direction has no length");
    EXPECT_EQ(errorOf("0,0,0,0,nan,0,0\n"), "track.csv:1: gaze_x is not finite");
    EXPECT_EQ(errorOf("1,0,0,0,1,0,0\n1,0,0,0,1,0,0\n"), "track.csv:2: time 1.000000 does not follow 1.000000");
    EXPECT_EQ(errorOf("0,0,0,1e300,1,0,0\n"), "track.csv:1: eye position out of range");
    EXPECT_EQ(errorOf("time,a,b\n# only a header\n"), "track.csv:2: no samples in the track");
    EXPECT_EQ(errorOf("0,0,0,0,1,0,\n"), "track.csv:1: gaze_z: \"\" is not a number");
}

TEST(GazeSource, missingTrackFileIsAnError) {
    EXPECT_THROW(readGazeTrackCsv("/nonexistent/track.csv"), GazeTrackError);
}

TEST(GazeSource, pixelAtViewCentreLooksForward) {
    const View v = View::lookAt({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60.0f, {640, 480});
    const glm::vec3 d = gazeThroughPixel(v, {320, 240});
    EXPECT_NEAR(d.z, -1.0f, 1e-5f);
    // Top-left pixel: up and to the left.
    const glm::vec3 corner = gazeThroughPixel(v, {0, 0});
    EXPECT_LT(corner.x, 0.0f);
    EXPECT_GT(corner.y, 0.0f);
}

TEST(GazeSource, mutatedTracksParseOrThrowGazeTrackError) {
    const std::string good = "time,eye_x,eye_y,eye_z,gaze_x,gaze_y,gaze_z\n0,0,1.6,0,0,0,-1\n0.5,0.1,1.6,0,0.2,0,-1\n";
    const char alphabet[] = "0123456789.,-+eE\n\r# naix";
    std::uint32_t state = 777;
    const auto next = [&state] { return state = state * 1664525u + 1013904223u; };
    for (int round = 0; round < 3000; ++round) {
        std::string text = good;
        for (int k = 0; k < 1 + round % 5; ++k) text[next() % text.size()] = alphabet[next() % (sizeof alphabet - 1)];
        try {
            const std::vector<GazeSample> samples = parseGazeTrackCsv(text, "t.csv");
            for (std::size_t i = 0; i < samples.size(); ++i) {
                ASSERT_NEAR(glm::length(samples[i].direction), 1.0f, 1e-5f);
                if (i) {
                    ASSERT_GT(samples[i].time, samples[i - 1].time);
                }
            }
        } catch (const GazeTrackError&) {}
    }
}
