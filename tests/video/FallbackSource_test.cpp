#include "video/sources/FallbackSource.hpp"
#include "video/sources/OpenSource.hpp"

#include <gtest/gtest.h>

#include <thread>

using namespace arcomp;

namespace {

// A primary whose frames and state the test sets by hand.
class ScriptedSource : public FrameSource {
public:
    std::optional<Frame> next;
    SourceState current{SourceStatus::Streaming, {}};
    void open() override {}
    std::optional<Frame> newest() override { return std::exchange(next, std::nullopt); }
    SourceState state() const override { return current; }
    std::uint64_t drops() const override { return 0; }
    void close() override {}
    std::string name() const override { return "scripted cam"; }
};

Frame frameOf(std::uint64_t seq, std::uint8_t grey) {
    return {cv::Mat(8, 8, CV_8UC3, cv::Scalar::all(grey)), {}, std::chrono::steady_clock::now(), seq, PixelFormat::Bgr};
}

}  // namespace

TEST(FallbackSource, showsStillImageWhileLostAndSwitchesBack) {
    auto owned = std::make_unique<ScriptedSource>();
    ScriptedSource* cam = owned.get();
    FallbackSource src(std::move(owned), FallbackKind::Image, nullptr, cv::Mat(8, 8, CV_8UC3, cv::Scalar::all(77)));
    cam->next = frameOf(0, 10);
    ASSERT_TRUE(src.newest());
    EXPECT_FALSE(src.showingFallback());

    cam->current = {SourceStatus::Disconnected, "/dev/video0 unplugged"};
    std::optional<Frame> still = src.newest();
    ASSERT_TRUE(still);
    EXPECT_EQ(still->image.at<cv::Vec3b>(0, 0)[0], 77);
    EXPECT_TRUE(src.showingFallback());
    EXPECT_NE(src.lastSwitchReason().find("/dev/video0 unplugged"), std::string::npos) << src.lastSwitchReason();
    EXPECT_FALSE(src.newest());  // the still is handed over once

    cam->current = {SourceStatus::Streaming, {}};
    cam->next = frameOf(1, 20);
    std::optional<Frame> back = src.newest();
    ASSERT_TRUE(back);
    EXPECT_EQ(back->image.at<cv::Vec3b>(0, 0)[0], 20);
    EXPECT_FALSE(src.showingFallback());
    EXPECT_EQ(src.switches(), 2u);
}

TEST(FallbackSource, lastGoodFrameIsRepeatedWhenLost) {
    auto owned = std::make_unique<ScriptedSource>();
    ScriptedSource* cam = owned.get();
    FallbackSource src(std::move(owned), FallbackKind::LastGoodFrame, nullptr);
    cam->next = frameOf(5, 42);
    src.newest();
    cam->current = {SourceStatus::Error, "damaged"};
    std::optional<Frame> f = src.newest();
    ASSERT_TRUE(f);
    EXPECT_EQ(f->image.at<cv::Vec3b>(0, 0)[0], 42);
}

TEST(FallbackSource, stalledCameraDoesNotSwitch) {
    auto owned = std::make_unique<ScriptedSource>();
    ScriptedSource* cam = owned.get();
    FallbackSource src(std::move(owned), FallbackKind::LastGoodFrame, nullptr);
    cam->current = {SourceStatus::Stalled, "no frame for 100 ms"};
    EXPECT_FALSE(src.newest());
    EXPECT_FALSE(src.showingFallback());
}

TEST(OpenSource, missingFileWithPatternFallbackShowsPattern) {
    SourceSpec spec;
    spec.kind = SourceKind::File;
    spec.path = "/nonexistent/camera-stand-in.avi";
    spec.width = 64;
    spec.height = 48;
    spec.fps = 100;
    spec.fallback.kind = FallbackKind::Pattern;
    std::unique_ptr<FrameSource> src = openSource(spec);
    std::optional<Frame> f;
    for (int i = 0; i < 400 && !f; ++i) {
        f = src->newest();
        if (!f) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    ASSERT_TRUE(f);
    EXPECT_EQ(f->image.size(), cv::Size(64, 48));
    EXPECT_EQ(src->state().status, SourceStatus::Error);
    EXPECT_NE(src->state().reason.find("does not exist"), std::string::npos) << src->state().reason;
    EXPECT_TRUE(dynamic_cast<FallbackSource&>(*src).showingFallback());
}
