// The station's pipelining: the next frame is captured and matted on one
// thread of the station's own while this one renders, yet every frame is
// shown in order with its own image and person layer, a damaged frame read
// ahead throws from its own frame(), and a hand-over passes on the frame
// read ahead.

#include "runtime/gl/GlContext.hpp"
#include "runtime/station/Station.hpp"
#include "video/pixels/VideoError.hpp"
#include "video/sources/FrameGrabber.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <unistd.h>

using namespace arcomp;

namespace {

// A recorded video of `count` flat grey frames, frame i at grey level 20 i,
// 30 fps: what a frame shows says which frame it is.
class NumberedFrames : public FrameGrabber {
public:
    explicit NumberedFrames(int count) : count_(count) {}
    GrabResult grab() override {
        if (next_ == count_)
            return {std::nullopt, {SourceStatus::Ended, "end after " + std::to_string(count_) + " frames"}};
        Frame f{cv::Mat(48, 64, CV_8UC3, cv::Scalar::all(20 * next_))};
        f.timestamp = std::chrono::milliseconds(100 * next_ / 3);
        f.sequence = static_cast<std::uint64_t>(next_++);
        return {std::move(f), {SourceStatus::Streaming, ""}};
    }
    std::string name() const override { return "numbered frames"; }

private:
    int count_;
    int next_ = 0;
};

// NumberedFrames that notes the kernel thread id of each read, and throws
// as a damaged file does when asked for frame `damagedAt`.
class NotedFrames : public NumberedFrames {
public:
    NotedFrames(int count, std::vector<pid_t>& readers, int damagedAt = -1)
        : NumberedFrames(count), readers_(readers), damagedAt_(damagedAt) {}
    GrabResult grab() override {
        if (static_cast<int>(readers_.size()) == damagedAt_)
            throw VideoError("numbered.avi", "frame " + std::to_string(damagedAt_), "damaged");
        readers_.push_back(::gettid());
        return NumberedFrames::grab();
    }

private:
    std::vector<pid_t>& readers_;
    int damagedAt_;
};

// Which frame the composited frame shows, from its top-left pixel (no CG
// is there; the person layer over its own video keeps the grey, give or
// take rounding).
int shownFrame(const Station& station) { return (station.compositedFrame().read().rgba[0] + 10) / 20; }

}  // namespace

// frame() returns only once the next frame's capture and matte are done, so
// a plate or person layer shared with the frame read ahead would hold that
// frame's grey by now, whichever thread ran first.
TEST(Station, aShownFrameKeepsItsPlateAndItsPersonLayerWhileTheNextIsMade) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    StationConfig cfg;
    cfg.file = "numbered.yaml";
    cfg.compositing.matte.kind = MatteKind::Chroma;  // keyed on green: every grey pixel is "person"
    Station station(cfg, StationInput::fromReplay(std::make_unique<NumberedFrames>(6), 30.0));
    for (int i = 0; i < 6; ++i) {
        ASSERT_TRUE(station.frame());
        ASSERT_FALSE(station.videoPlate().empty());
        EXPECT_EQ(station.videoPlate().at<cv::Vec4b>(0, 0), cv::Vec4b(20 * i, 20 * i, 20 * i, 255)) << "frame " << i;
        EXPECT_EQ(station.personLayer().at<cv::Vec4b>(0, 0), cv::Vec4b(20 * i, 20 * i, 20 * i, 255)) << "frame " << i;
    }
}

// The station reads one frame ahead (capture and matte of frame N+1 while
// frame N renders), yet every frame is composited once, in order, with its
// own image, up to the last one of the file; a station that hands its input
// on (a reload) passes on the frame it had read ahead.
TEST(Station, aPipelinedReplayShowsEveryFrameInOrderAcrossAHandOver) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    StationConfig cfg;
    cfg.file = "numbered.yaml";
    std::vector<int> shown;
    StationInput input = StationInput::fromReplay(std::make_unique<NumberedFrames>(10), 30.0);
    {
        Station first(cfg, std::move(input));
        for (int i = 0; i < 4; ++i) {
            ASSERT_TRUE(first.frame());
            shown.push_back(shownFrame(first));
            EXPECT_EQ(first.personLayer().size(), cv::Size(64, 48));
        }
        input = first.releaseInput();
    }
    Station second(cfg, std::move(input));
    while (second.frame()) shown.push_back(shownFrame(second));
    EXPECT_EQ(shown, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
    EXPECT_EQ(second.inputEnd(), "end after 10 frames");
    EXPECT_FALSE(second.frame()) << "an ended input stays ended";
}

// The frame read ahead is read on one thread for the station's life. Kernel
// thread ids, not std::thread::id: glibc hands a joined thread's stack and
// pthread_t to the next one, the kernel never reuses an id this soon. A
// thread started per frame (std::async did) reads each frame on a new one.
TEST(Station, everyFrameIsReadAheadOnTheSameThreadForTheStationsLife) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    StationConfig cfg;
    cfg.file = "numbered.yaml";
    std::vector<pid_t> readers;
    Station station(cfg, StationInput::fromReplay(std::make_unique<NotedFrames>(30, readers), 30.0));
    while (station.frame()) {}
    ASSERT_EQ(readers.size(), 31u) << "30 frames, then the read that finds the end";
    EXPECT_EQ(readers[0], ::gettid()) << "the first frame is read as the station starts";
    const std::set<pid_t> ahead(readers.begin() + 1, readers.end());
    EXPECT_EQ(ahead.size(), 1u) << "reads 1-30 ran on " << ahead.size() << " threads";
    EXPECT_FALSE(ahead.contains(::gettid()));
}

// What the read-ahead throws (a damaged file) comes out of the frame() that
// would have shown that frame, after every frame before it was shown; the
// station then ends cleanly.
TEST(Station, aDamagedFrameReadAheadThrowsFromTheFrameItBelongsTo) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    StationConfig cfg;
    cfg.file = "numbered.yaml";
    std::vector<pid_t> readers;
    std::vector<int> shown;
    {
        Station station(cfg, StationInput::fromReplay(std::make_unique<NotedFrames>(10, readers, 4), 30.0));
        for (int i = 0; i < 4; ++i) {
            ASSERT_TRUE(station.frame());
            shown.push_back(shownFrame(station));
        }
        try {
            station.frame();
            ADD_FAILURE() << "frame 4 is damaged, yet it was shown";
        } catch (const VideoError& e) {
            EXPECT_EQ(e.where, "frame 4");
        }
    }
    EXPECT_EQ(shown, (std::vector<int>{0, 1, 2, 3}));
}
