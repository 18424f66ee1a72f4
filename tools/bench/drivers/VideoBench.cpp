// arcomp-bench video: what a frame costs from file to BGR pixels, and what
// newest-frame delivery does to latency and drops.
//  - decode: FileSource over vtest.avi and over a 1920x1080 MJPEG file the
//    benchmark writes with cv::VideoWriter; baseline: a bare VideoCapture
//    read loop over the same files (what our wrapper costs on top).
//  - yuyv_convert: our matrix/range-aware YUYV->BGR at 1080p; baseline:
//    OpenCV's cvtColor(COLOR_YUV2BGR_YUYV), which knows only BT.601 limited.
//    Medians of 60, alternating, each into a new image. Target: ours <= cvtColor.
//  - latency: the 1080p file paced at 30 fps through a CaptureThread, polled
//    every millisecond: frame capture time to the moment the consumer has it.
//    Target: <= one frame period + decode time.
//  - drops: the same source with a consumer at 10 Hz; the slot holds one
//    frame, so everything in between is dropped and counted, never queued.

#include "graph/core/ElapsedTime.hpp"
#include "tools/bench/report/BenchJson.hpp"
#include "tools/bench/report/Stats.hpp"
#include "tools/cli/Command.hpp"
#include "video/pixels/YuvConversion.hpp"
#include "video/sources/CaptureThread.hpp"
#include "video/sources/FileSource.hpp"
#include "video/sources/TestPatternSource.hpp"

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include <unistd.h>

namespace arcomp {
namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

struct DecodeTiming {
    int frames = 0;
    double oursMs = 0, baselineMs = 0;  // per frame
};

DecodeTiming timeDecode(const std::string& path) {
    DecodeTiming t;
    {
        FileSource file({.path = path});
        const auto t0 = Clock::now();
        while (file.next()) ++t.frames;
        t.oursMs = msSince(t0) / std::max(1, t.frames);
    }
    cv::VideoCapture cap(path, cv::CAP_FFMPEG);
    cv::Mat img;
    int n = 0;
    const auto t0 = Clock::now();
    while (cap.read(img)) ++n;
    t.baselineMs = msSince(t0) / std::max(1, n);
    return t;
}

std::string writeHdMjpeg(const fs::path& dir, int frames) {
    const fs::path out = dir / "bench-1080p-mjpeg.avi";
    cv::VideoWriter writer(out.string(), cv::CAP_FFMPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 30.0,
                           cv::Size(1920, 1080));
    if (!writer.isOpened()) throw std::runtime_error("cannot write " + out.string() + " with FFmpeg MJPEG");
    TestPatternSource pattern({.width = 1920, .height = 1080, .fps = 30, .paced = false});
    for (int i = 0; i < frames; ++i) writer.write(pattern.render(static_cast<std::uint64_t>(i)));
    return out.string();
}

struct DeliveryStats {
    int taken = 0;
    std::uint64_t drops = 0;
    double meanMs = 0, p95Ms = 0, maxMs = 0;
};

DeliveryStats measureDelivery(const std::string& path, std::chrono::milliseconds pollEvery,
                              std::chrono::seconds runFor) {
    CaptureThread src(
        path, [path] { return std::make_unique<FileSource>(FileOptions{.path = path, .paced = true, .loop = true}); });
    src.open();
    std::vector<double> lat;
    const auto end = Clock::now() + runFor;
    while (Clock::now() < end) {
        if (std::optional<Frame> f = src.newest())
            lat.push_back(std::chrono::duration<double, std::milli>(Clock::now() - f->captured).count());
        std::this_thread::sleep_for(pollEvery);
    }
    src.close();
    DeliveryStats s;
    s.taken = static_cast<int>(lat.size());
    s.drops = src.drops();
    if (!lat.empty()) {
        double sum = 0;
        for (double v : lat) sum += v;
        s.meanMs = sum / lat.size();
        s.p95Ms = percentile(lat, 95);
        s.maxMs = *std::max_element(lat.begin(), lat.end());
    }
    return s;
}

int videoBench(const std::string& vtest) {
    const fs::path dir = fs::temp_directory_path() / ("arcomp-bench-video-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::fprintf(stderr, "bench video: writing 1080p MJPEG into %s\n", dir.c_str());
    const std::string hd = writeHdMjpeg(dir, 90);

    const bool haveVtest = fs::exists(vtest);
    DecodeTiming sd;
    if (haveVtest) {
        std::fprintf(stderr, "bench video: decoding %s\n", vtest.c_str());
        sd = timeDecode(vtest);
    }
    std::fprintf(stderr, "bench video: decoding %s\n", hd.c_str());
    const DecodeTiming hdt = timeDecode(hd);

    // YUYV conversion at 1080p, ours (BT.709 limited) against OpenCV's BT.601-only cvtColor.
    const cv::Mat scene = TestPatternSource({.width = 1920, .height = 1080, .fps = 30, .paced = false}).render(0);
    const YuvEncoding e{YuvMatrix::Bt709, YuvRange::Limited};
    const std::vector<std::uint8_t> yuyv = bgrToYuyv(scene, e);
    // Alternating, and each into a new image: a converter hands every frame
    // downstream, so neither side may reuse its output.
    const cv::Mat packed(1080, 1920, CV_8UC2, const_cast<std::uint8_t*>(yuyv.data()));
    std::vector<double> oursMs, cvMs;
    for (int i = 0; i < 60; ++i) {
        auto t0 = Clock::now();
        cv::Mat ours = yuyvToBgr(yuyv.data(), 1920, 1080, 3840, e);
        oursMs.push_back(msSince(t0));
        t0 = Clock::now();
        cv::Mat theirs;
        cv::cvtColor(packed, theirs, cv::COLOR_YUV2BGR_YUYV);
        cvMs.push_back(msSince(t0));
    }
    const double oursYuyv = median(oursMs), cvYuyv = median(cvMs);

    std::fprintf(stderr, "bench video: newest-frame latency, 1080p MJPEG paced at 30 fps, consumer polls every 1 ms\n");
    const DeliveryStats fast = measureDelivery(hd, std::chrono::milliseconds(1), std::chrono::seconds(3));
    std::fprintf(stderr, "bench video: drops with a 10 Hz consumer\n");
    const DeliveryStats slow = measureDelivery(hd, std::chrono::milliseconds(100), std::chrono::seconds(3));
    fs::remove_all(dir);

    const double periodMs = 1000.0 / 30.0;
    const double latencyTargetMs = periodMs + hdt.oursMs;
    // Milliseconds to the microsecond, as this bench has always reported them.
    const auto ms = [](double x) { return Fixed{x, 3}; };
    BenchJson j;
    j.field("bench", "video");
    if (haveVtest)
        j.beginObject("vtest")
            .field("frames", sd.frames)
            .field("decode_convert_ms", ms(sd.oursMs))
            .field("baseline_videocapture_ms", ms(sd.baselineMs))
            .end();
    else
        j.null("vtest");
    j.beginObject("mjpeg_1080p")
        .field("frames", hdt.frames)
        .field("decode_convert_ms", ms(hdt.oursMs))
        .field("baseline_videocapture_ms", ms(hdt.baselineMs))
        .end();
    j.field("yuyv_1080p_convert_ms", ms(oursYuyv)).field("baseline_cvtColor_bt601_ms", ms(cvYuyv));
    j.beginObject("latency")
        .field("source_fps", 30)
        .field("frames", fast.taken)
        .field("mean_ms", ms(fast.meanMs))
        .field("p95_ms", ms(fast.p95Ms))
        .field("max_ms", ms(fast.maxMs))
        .field("target_ms", ms(latencyTargetMs))
        .field("p95_within_target", fast.p95Ms <= latencyTargetMs)
        .field("drops", fast.drops)
        .end();
    j.beginObject("slow_consumer")
        .field("source_fps", 30)
        .field("consumer_hz", 10)
        .field("frames_taken", slow.taken)
        .field("drops", slow.drops)
        .field("mean_latency_ms", ms(slow.meanMs))
        .field("queue_capacity", 1)
        .end();
    std::printf("%s\n", j.str().c_str());
    return kExitOk;
}

const bool registered =
    registerCommand({"video", "Decode+convert cost, newest-frame latency and drops", [](CommandLine& line) {
                         auto vtest =
                             std::make_shared<std::string>("/usr/share/doc/opencv-doc/examples/data/vtest.avi");
                         line.option("--vtest", *vtest, "The 768x576 reference clip").showDefault();
                         return [vtest] { return videoBench(*vtest); };
                     }});

}  // namespace
}  // namespace arcomp
