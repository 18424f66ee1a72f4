// arcomp-bench soak [--frames N] [--config FILE] [--video FILE]: a looping
// video through the whole station (StationRunner + Station: capture, matte,
// select, render, composite), headless and unpaced, for N frames. Reports
// resident memory and open file descriptors after warm-up and at the end,
// and frame-time drift (median of the first window after warm-up against
// the last window), in wall time and in the process's CPU time (all
// threads, llvmpipe's included). Targets: RSS growth <= 2 MB, no fd growth,
// no drift: the last CPU-time median within 10 % or 1 ms of the first. The
// verdict uses CPU time because wall time on a shared machine drifts with
// whatever else runs; both are reported.
//
// Without --config it composites the demo scene (three shapes, MOG2 matte)
// over vtest.avi, or over a clip it generates when opencv-doc is absent.
// With --config, that station's video is forced to loop and its file
// outputs are dropped, so a soak never fills a disk.

#include "graph/core/ElapsedTime.hpp"
#include "runtime/app/StationRunner.hpp"
#include "runtime/gl/GlContext.hpp"
#include "runtime/operator/ProcessMemory.hpp"
#include "runtime/station/ReplayInput.hpp"
#include "tools/bench/report/BenchJson.hpp"
#include "tools/bench/report/Stats.hpp"
#include "tools/bench/scenes/DemoStation.hpp"
#include "tools/cli/Command.hpp"

#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace arcomp {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct SoakOptions {
    long frames = 50000;
    std::string config;
    std::string video = kDemoVideo;
};

constexpr double kRssGrowthLimitMb = 2.0;
constexpr double kDriftLimitRatio = 0.10;
constexpr double kDriftLimitMs = 1.0;

constexpr double kMb = 1024.0 * 1024.0;

double mb(std::size_t bytes) { return static_cast<double>(bytes) / kMb; }

// Least-squares slope of y over x.
double slope(std::span<const double> x, std::span<const double> y) {
    const double n = static_cast<double>(x.size());
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
    }
    const double d = n * sxx - sx * sx;
    return d > 0 ? (n * sxy - sx * sy) / d : 0.0;
}

int soak(const SoakOptions& o) {
    if (o.frames < 100) throw InputError("--frames must be at least 100 (warm-up and two windows)");
    const fs::path dir = fs::temp_directory_path() / ("arcomp-bench-soak-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string video = o.config.empty() ? demoVideo(dir, "bench soak", o.video) : o.video;
    fs::path configFile = o.config;
    if (configFile.empty()) {
        configFile = dir / "soak.yaml";
        std::ofstream(configFile) << demoStationYaml(video);
    }
    StationConfig cfg = loadStationConfig(configFile);
    if (!cfg.compositing.video) throw InputError(configFile.string() + ": no `video` section to loop");
    cfg.compositing.video->loop = true;
    cfg.compositing.output = {};
    cfg.operation = {};  // no status port, no log file: the soak measures the pipeline alone

    auto context = HeadlessContext::create(GlRequest::Auto);
    StationRunner runner(cfg, nullptr, [](const StationConfig& c) {
        std::vector<std::string> warnings;
        return openReplayInput(*c.compositing.video, warnings);
    });

    // Warm-up: the matte's model fills, allocator pools and driver caches
    // reach their steady size. A tenth of the run, uncapped: llvmpipe takes
    // a new 1 MiB block inside a draw now and then (every couple of thousand
    // frames for a one-box station, heaptrack shows), and RSS reaches its
    // plateau only once freed ones come back round, within the first 5,000.
    const long warmup = std::max(o.frames / 10, 50L);
    const long window = std::clamp(o.frames / 10, 25L, 1000L);
    // The bench's own records stay the same size all run, or the RSS figure
    // would count them: the first window after warm-up, and a ring of the
    // last window, both allocated (and written) before the RSS baseline.
    struct Window {
        std::vector<double> first, last;
        std::size_t firstCount = 0;
    };
    const auto size = static_cast<std::size_t>(window);
    Window wallMs{std::vector<double>(size, 0.0), std::vector<double>(size, 0.0)}, cpuMs = wallMs;
    const auto record = [&](Window& w, long frame, double ms) {
        if (frame >= warmup && frame < warmup + window) w.first[w.firstCount++] = ms;
        w.last[static_cast<std::size_t>(frame % window)] = ms;
    };
    double rssStart = 0.0, rssPeak = 0.0, heapStart = 0.0;
    int fdStart = 0;
    // RSS every 1,000 frames after warm-up, for the slope.
    std::vector<double> sampleFrames, sampleRss;
    sampleFrames.reserve(static_cast<std::size_t>(o.frames / 1000 + 2));
    sampleRss.reserve(sampleFrames.capacity());
    long done = 0;
    const auto begin = Clock::now();
    while (done < o.frames) {
        const auto t0 = Clock::now();
        const double c0 = processCpuMs();
        if (!runner.step())
            throw std::runtime_error("the looping input ended after " + std::to_string(done) + " frames");
        record(wallMs, done, std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
        record(cpuMs, done, processCpuMs() - c0);
        ++done;
        // Read every 100 frames, the peak too: listing the fds every frame would weigh on the frame times.
        if (done < warmup || (done != warmup && done % 100 != 0)) continue;
        const ProcessMemory m = ProcessMemory::now();
        if (done == warmup) {
            rssStart = mb(m.resident);
            heapStart = mb(m.heapInUse);
            fdStart = m.fileDescriptors;
        }
        rssPeak = std::max(rssPeak, mb(m.resident));
        if (done % 1000 == 0) {
            sampleFrames.push_back(static_cast<double>(done));
            sampleRss.push_back(mb(m.resident));
            std::fprintf(stderr, "bench soak: frame %ld, RSS %.1f MB, heap in use %.2f MB, fds %d\n", done,
                         mb(m.resident), mb(m.heapInUse), m.fileDescriptors);
        }
    }
    const ProcessMemory end = ProcessMemory::now();
    const double rssEnd = mb(end.resident), heapEnd = mb(end.heapInUse);
    const int fdEnd = end.fileDescriptors;
    const double seconds = std::chrono::duration<double>(Clock::now() - begin).count();
    runner.finish();
    fs::remove_all(dir);

    struct Drift {
        double first, last;
    };
    const auto drift = [&](const Window& w) {
        return Drift{median(std::span(w.first).first(w.firstCount)), median(w.last)};
    };
    const Drift wall = drift(wallMs), cpu = drift(cpuMs);
    const double driftLimit = std::max(kDriftLimitMs, kDriftLimitRatio * cpu.first);
    const bool rssOk = rssEnd - rssStart <= kRssGrowthLimitMb;
    const bool fdOk = fdEnd <= fdStart;
    const bool driftOk = cpu.last - cpu.first <= driftLimit;

    // Rounded as this bench has always reported them: memory to 10 kB, times to the microsecond.
    BenchJson j;
    j.field("bench", "soak")
        .field("frames", o.frames)
        .field("warmup_frames", warmup)
        .field("window_frames", window)
        .field("seconds", Fixed{seconds, 1})
        .field("input", o.config.empty() ? fs::path(video).filename().string() : o.config);
    j.beginArray("size").value(runner.station().size().x).value(runner.station().size().y).end();
    j.beginObject("rss_mb")
        .field("start", Fixed{rssStart, 2})
        .field("end", Fixed{rssEnd, 2})
        .field("peak", Fixed{rssPeak, 2})
        .field("growth", Fixed{rssEnd - rssStart, 2})
        .field("slope_per_1000_frames", Fixed{1000.0 * slope(sampleFrames, sampleRss), 4})
        .field("limit", Fixed{kRssGrowthLimitMb, 1})
        .field("ok", rssOk)
        .end();
    j.beginObject("heap_in_use_mb")
        .field("start", Fixed{heapStart, 2})
        .field("end", Fixed{heapEnd, 2})
        .field("growth", Fixed{heapEnd - heapStart, 3})
        .end();
    j.beginObject("fds").field("start", fdStart).field("end", fdEnd).field("ok", fdOk).end();
    j.beginObject("frame_ms")
        .field("wall_first_window_median", Fixed{wall.first, 3})
        .field("wall_last_window_median", Fixed{wall.last, 3})
        .field("wall_drift", Fixed{wall.last - wall.first, 3})
        .field("cpu_first_window_median", Fixed{cpu.first, 3})
        .field("cpu_last_window_median", Fixed{cpu.last, 3})
        .field("cpu_drift", Fixed{cpu.last - cpu.first, 3})
        .field("limit", Fixed{driftLimit, 3})
        .field("ok", driftOk)
        .end();
    std::printf("%s\n", j.str().c_str());
    return kExitOk;
}

const bool registered = registerCommand(
    {"soak", "Loop a video through the whole station: RSS, open fds and frame-time drift", [](CommandLine& line) {
         auto o = std::make_shared<SoakOptions>();
         line.option("--frames", o->frames, "Frames to run (the issue's figure is 50000)").showDefault();
         line.option("--config", o->config, "Soak this station instead of the demo scene (video looped, outputs off)");
         line.option("--video", o->video, "Clip for the demo scene (generated when absent)").showDefault();
         return [o] { return soak(*o); };
     }});

}  // namespace
}  // namespace arcomp
