// The capture stage's clocks: the time of the frame on screen, which model
// animations run on, from the frames' own stamps (no waiting, no timing).

#include "runtime/station/CaptureStage.hpp"
#include "video/sources/TestPatternSource.hpp"

#include <gtest/gtest.h>

#include <deque>

using namespace arcomp;
using namespace std::chrono_literals;

namespace {

// A live camera that hands over a scripted list of frames, one per
// newest() call; an empty entry is "nothing new".
class ScriptedCamera : public FrameSource {
public:
    explicit ScriptedCamera(std::deque<std::optional<Frame>> frames) : frames_(std::move(frames)) {}
    void open() override {}
    std::optional<Frame> newest() override {
        if (frames_.empty()) return std::nullopt;
        std::optional<Frame> f = std::move(frames_.front());
        frames_.pop_front();
        return f;
    }
    SourceState state() const override { return {SourceStatus::Streaming, ""}; }
    std::uint64_t drops() const override { return 0; }
    void close() override {}
    std::string name() const override { return "scripted"; }

private:
    std::deque<std::optional<Frame>> frames_;
};

Frame capturedAt(std::chrono::steady_clock::time_point t) {
    Frame f;
    f.image = cv::Mat(4, 4, CV_8UC3, cv::Scalar(0, 0, 0));
    f.captured = t;
    return f;
}

}  // namespace

// Live: the capture time of the frame shown, since the station's clock
// start; unchanged while the camera has nothing new, and never backwards
// when a source with another timeline (a fallback) takes over.
TEST(CaptureStage, liveFrameSecondsAreTheShownFramesCaptureTime) {
    const auto start = std::chrono::steady_clock::time_point{} + 1000s;
    std::deque<std::optional<Frame>> frames;
    frames.push_back(capturedAt(start + 500ms));
    frames.push_back(std::nullopt);
    frames.push_back(capturedAt(start + 1250ms));
    frames.push_back(capturedAt(start + 1000ms));
    CaptureStage capture(StationInput::fromLive(std::make_unique<ScriptedCamera>(std::move(frames)), 30.0));
    capture.setClockStart(start);
    ASSERT_TRUE(capture.next());
    EXPECT_DOUBLE_EQ(capture.frameSeconds(), 0.5);
    ASSERT_TRUE(capture.next());
    EXPECT_FALSE(capture.newFrame());
    EXPECT_DOUBLE_EQ(capture.frameSeconds(), 0.5);
    ASSERT_TRUE(capture.next());
    EXPECT_DOUBLE_EQ(capture.frameSeconds(), 1.25);
    ASSERT_TRUE(capture.next());
    EXPECT_DOUBLE_EQ(capture.frameSeconds(), 1.25);
}

// Replay: the video's own timestamps, the same as seconds().
TEST(CaptureStage, replayFrameSecondsAreTheVideoTimestamps) {
    CaptureStage capture(StationInput::fromReplay(
        std::make_unique<TestPatternSource>(TestPatternOptions{.width = 32, .height = 24, .fps = 20.0, .paced = false}),
        20.0));
    for (int i = 0; i < 5; ++i) {
        ASSERT_TRUE(capture.next());
        EXPECT_DOUBLE_EQ(capture.frameSeconds(), capture.seconds());
        EXPECT_NEAR(capture.frameSeconds(), i / 20.0, 1e-9);
    }
}
