// A station that runs all day holds no more memory frame after frame: a
// short soak, after warm-up, of the pattern station and of the demo
// installation (consensus matte, people's depths, contact shadows). It
// guards against what once grew a station by about 0.9 KB a frame: a new
// thread started every frame, whose OpenCV per-thread data outlived it
// (runtime/station/WorkerThread.hpp).
//
// Two measures, each the peak over a window of frames, three windows after
// the warm-up, each with its own limit on the growth per frame:
// - the heap bytes in use (runtime/operator/ProcessMemory.hpp), from the first
//   window to the last: flat to a few bytes a frame on the fixed code, so
//   its limit is tight;
// - RSS, which also counts the allocator settling on its pages: a step of
//   about 1 MB now and then, once, which one window pair alone cannot tell
//   from a leak. A leak grows every window, so the figure is the smaller of
//   the two pairs' growths.
// Measured on both sides of the limits (the test prints its own figures):
// - the fixed code, four runs of each station in the plain build and one
//   in the sanitized one: heap -0.1 to +7.3 B/frame; RSS's smaller growth
//   0 B/frame or less, while a single window pair reached +783 (sanitized)
//   and +430 (plain) B/frame;
// - a thread a frame (the code before runtime/WorkerThread): heap +834 and
//   +842 B/frame, RSS's smaller growth +799 and +840 B/frame.

#include "runtime/gl/GlContext.hpp"
#include "runtime/operator/ProcessMemory.hpp"
#include "runtime/station/ReplayInput.hpp"
#include "runtime/station/Station.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

using namespace arcomp;
namespace fs = std::filesystem;

namespace {

constexpr int kWarmupFrames = 800;
// Longer than one loop of the demo's video (vtest.avi, 795 frames): how
// much a station holds follows what it sees (how many people, how big),
// so each measure is the peak over a whole loop, the same loop each time.
constexpr int kWindowFrames = 800;
constexpr double kHeapLimitBytesPerFrame = 64.0;
constexpr double kRssLimitBytesPerFrame = 400.0;

struct Growth {
    double heapBytesPerFrame, rssBytesPerFrame;
};

struct Peak {
    std::size_t heapInUse = 0, resident = 0;
    int fileDescriptors = 0;
};

Peak peakOver(Station& station, int frames) {
    Peak p;
    for (int i = 0; i < frames; ++i) {
        EXPECT_TRUE(station.frame());
        const ProcessMemory m = ProcessMemory::now();
        p.heapInUse = std::max(p.heapInUse, m.heapInUse);
        p.resident = std::max(p.resident, m.resident);
        p.fileDescriptors = std::max(p.fileDescriptors, m.fileDescriptors);
    }
    return p;
}

double perFrame(std::size_t from, std::size_t to, int frames) {
    return (static_cast<double>(to) - static_cast<double>(from)) / frames;
}

// Replays `cfg` (its video looped, no outputs) for the warm-up, then three
// windows.
Growth soak(StationConfig cfg) {
    cfg.compositing.video->loop = true;
    cfg.compositing.output = {};
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    std::vector<std::string> warnings;
    Station station(cfg, openReplayInput(*cfg.compositing.video, warnings));
    for (int i = 0; i < kWarmupFrames; ++i) EXPECT_TRUE(station.frame());
    const Peak first = peakOver(station, kWindowFrames);
    const Peak second = peakOver(station, kWindowFrames);
    const Peak third = peakOver(station, kWindowFrames);
    EXPECT_LE(third.fileDescriptors, first.fileDescriptors);
    const Growth g{perFrame(first.heapInUse, third.heapInUse, 2 * kWindowFrames),
                   std::min(perFrame(first.resident, second.resident, kWindowFrames),
                            perFrame(second.resident, third.resident, kWindowFrames))};
    std::printf("soak guard: %s: three windows of %d frames after %d of warm-up: peak heap %+.1f B/frame (limit %.0f), "
                "peak RSS %+.1f then %+.1f B/frame (limit %.0f on the smaller)\n",
                cfg.file.filename().c_str(), kWindowFrames, kWarmupFrames, g.heapBytesPerFrame, kHeapLimitBytesPerFrame,
                perFrame(first.resident, second.resident, kWindowFrames),
                perFrame(second.resident, third.resident, kWindowFrames), kRssLimitBytesPerFrame);
    return g;
}

void expectFlat(const Growth& g) {
    EXPECT_LE(g.heapBytesPerFrame, kHeapLimitBytesPerFrame);
    EXPECT_LE(g.rssBytesPerFrame, kRssLimitBytesPerFrame);
}

}  // namespace

TEST(SoakGuard, patternStationHoldsNoMoreMemoryFrameAfterFrame) {
    expectFlat(soak(loadStationConfig(fs::path(ARCOMP_SOURCE_DIR) / "tests/runtime/soak-pattern.yaml")));
}

TEST(SoakGuard, demoInstallationHoldsNoMoreMemoryFrameAfterFrame) {
    // Without opencv-doc the demo replays its fallback pattern, matte, depths and shadows all the same.
    expectFlat(soak(loadStationConfig(fs::path(ARCOMP_SOURCE_DIR) / "configs/demo-replay.yaml")));
}
