// arcomp-bench stream: what streaming the composite costs, at 768x576 and at
// 1920x1080, with the stream's default settings (x264 veryfast,
// zerolatency, 4000 kbit/s, a keyframe every 2 s, 25 fps).
//  - encode: the process's CPU time per encoded frame while StreamOutputs
//    takes frames at 25 a second (an RTSP stream without clients: encoder,
//    parser and the server's intake, no network). The peer is GStreamer
//    itself, the same chain and settings fed by videotestsrc at 25 fps:
//      videotestsrc pattern=smpte horizontal-speed=4 is-live=true
//        ! video/x-raw,format=RGBA,framerate=25/1
//        ! videoconvert ! videoscale ! video/x-raw,format=I420
//        ! x264enc speed-preset=veryfast tune=zerolatency bitrate=4000
//        key-int-max=50 ! h264parse ! fakesink
//    less the CPU time of videotestsrc alone (the station pushes frames it
//    already has). Both encode the same pictures: the station is fed the
//    frames videotestsrc makes. Frames after the first 10 count.
//    Target: the station's cost <= 1.2x the peer's.
//  - latency: frames that carry their number, from StreamOutputs::push to
//    an SRT receiver in this process that has decoded them (srtsrc,
//    tsdemux, avdec_h264), on loopback with SRT's default 120 ms latency;
//    counted from 2 s after the first one decoded (the caller has
//    connected, and what waited for it has drained). The receiver's decoding shares this machine's cores.
//  - frame_time: the demo station (configs/demo-replay.yaml's scene and
//    matte over the test pattern, headless) paced at 25 fps, its frame
//    time without a stream, with an SRT stream to a receiver in this
//    process (which only takes the packets) and with an RTSP stream
//    without clients; medians and 95th percentiles over the same count.

#include "graph/core/ElapsedTime.hpp"
#include "runtime/config/StationConfig.hpp"
#include "runtime/gl/GlContext.hpp"
#include "runtime/station/Station.hpp"
#include "tools/bench/probes/LoopbackUdp.hpp"
#include "tools/bench/report/BenchJson.hpp"
#include "tools/bench/report/Stats.hpp"
#include "tools/bench/scenes/NumberedFrames.hpp"
#include "tools/cli/Command.hpp"
#include "video/sources/TestPatternSource.hpp"
#include "video/streams/GstRuntime.hpp"
#include "video/streams/StreamOutputs.hpp"

#include <gst/app/gstappsink.h>
#include <gst/gst.h>
#include <opencv2/imgproc.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace arcomp {
namespace {

using Clock = std::chrono::steady_clock;
constexpr double kFps = 25.0;
constexpr int kWarmup = 10;
const auto kFramePeriod = std::chrono::microseconds(40000);

struct StreamBenchOptions {
    std::string config = "configs/demo-replay.yaml";
    int frames = 100;
};

std::string sizeCaps(cv::Size size) {
    return "width=" + std::to_string(size.width) + ",height=" + std::to_string(size.height);
}

// A pipeline from gst_parse_launch, stopped and freed when it goes.
class LaunchedPipeline {
public:
    explicit LaunchedPipeline(const std::string& description) {
        GError* error = nullptr;
        pipeline_ = gst_parse_launch(description.c_str(), &error);
        if (error != nullptr) {
            const std::string why = error->message;
            g_error_free(error);
            if (pipeline_ != nullptr) gst_object_unref(pipeline_);
            throw std::runtime_error("cannot build `" + description + "`: " + why);
        }
    }
    ~LaunchedPipeline() {
        gst_element_set_state(pipeline_, GST_STATE_NULL);
        gst_object_unref(pipeline_);
    }
    LaunchedPipeline(const LaunchedPipeline&) = delete;
    LaunchedPipeline& operator=(const LaunchedPipeline&) = delete;

    GstElement* element(const char* name) const {
        GstElement* e = gst_bin_get_by_name(GST_BIN(pipeline_), name);
        if (e == nullptr) std::abort();  // the description names it
        gst_object_unref(e);             // the pipeline keeps it
        return e;
    }
    void play() {
        if (gst_element_set_state(pipeline_, GST_STATE_PLAYING) == GST_STATE_CHANGE_FAILURE)
            throw std::runtime_error("a GStreamer pipeline did not start");
    }
    // Until end of stream; throws with GStreamer's message on an error.
    void runToEnd() {
        play();
        GstBus* bus = gst_element_get_bus(pipeline_);
        GstMessage* m = gst_bus_timed_pop_filtered(bus, GST_CLOCK_TIME_NONE,
                                                   static_cast<GstMessageType>(GST_MESSAGE_EOS | GST_MESSAGE_ERROR));
        gst_object_unref(bus);
        std::string error;
        if (GST_MESSAGE_TYPE(m) == GST_MESSAGE_ERROR) {
            GError* e = nullptr;
            gst_message_parse_error(m, &e, nullptr);
            error = e->message;
            g_error_free(e);
        }
        gst_message_unref(m);
        if (!error.empty()) throw std::runtime_error("GStreamer: " + error);
    }

private:
    GstElement* pipeline_ = nullptr;
};

// Live, the peer takes frames at 25 a second as the station does: an
// encoder that sleeps between frames costs more per frame than one kept
// busy.
std::string testSource(cv::Size size, int frames, bool live) {
    return "videotestsrc pattern=smpte horizontal-speed=4 is-live=" + std::string(live ? "true" : "false") +
           " num-buffers=" + std::to_string(frames) + " ! video/x-raw,format=RGBA," + sizeCaps(size) +
           ",framerate=25/1";
}

// videotestsrc's first `count` frames, RGBA.
std::vector<std::vector<std::uint8_t>> testSourceFrames(cv::Size size, int count) {
    LaunchedPipeline p(testSource(size, count, false) + " ! appsink name=out sync=false");
    p.play();
    std::vector<std::vector<std::uint8_t>> frames;
    while (GstSample* s = gst_app_sink_pull_sample(GST_APP_SINK(p.element("out")))) {
        GstMapInfo map;
        GstBuffer* b = gst_sample_get_buffer(s);
        gst_buffer_map(b, &map, GST_MAP_READ);
        frames.emplace_back(map.data, map.data + map.size);
        gst_buffer_unmap(b, &map);
        gst_sample_unref(s);
    }
    return frames;
}

// CPU ms a frame of a pipeline run to its end, counted from the
// (kWarmup+1)th buffer leaving the element named "counted".
double pipelineCpuMsPerFrame(const std::string& description, int frames) {
    LaunchedPipeline p(description);
    struct Count {
        int buffers = 0;
        double cpuAtWarm = 0;
    } count;
    GstPad* pad = gst_element_get_static_pad(p.element("counted"), "src");
    gst_pad_add_probe(
        pad, GST_PAD_PROBE_TYPE_BUFFER,
        [](GstPad*, GstPadProbeInfo*, gpointer data) {
            auto* c = static_cast<Count*>(data);
            if (++c->buffers == kWarmup) c->cpuAtWarm = processCpuMs();
            return GST_PAD_PROBE_OK;
        },
        &count, nullptr);
    gst_object_unref(pad);
    p.runToEnd();
    return (processCpuMs() - count.cpuAtWarm) / (frames - kWarmup);
}

struct EncodeCost {
    double stationMs = 0, peerMs = 0, sourceMs = 0;
    std::uint64_t encoded = 0, dropped = 0;
};

StreamSpec rtspWithoutClients(const std::string& name) {
    StreamSpec s = parseStreamUrl("rtsp://127.0.0.1:" + std::to_string(LoopbackUdp().port()) + "/" + name);
    s.name = name;
    return s;
}

EncodeCost encodeCost(cv::Size size, int frames) {
    EncodeCost c;
    const int total = kWarmup + frames;
    const auto pictures = testSourceFrames(size, total);
    if (static_cast<int>(pictures.size()) != total) throw std::runtime_error("videotestsrc gave too few frames");
    {
        StreamOutputs out({rtspWithoutClients("encode")}, {size.width, size.height, kFps});
        double cpu0 = 0;
        std::uint64_t dropped0 = 0;
        auto next = Clock::now();
        for (int i = 0; i < total; ++i) {
            if (i == kWarmup) {
                std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the warm-up frames encoded
                cpu0 = processCpuMs();
                dropped0 = out.status().front().dropped;
                next = Clock::now();
            }
            out.push(pictures[static_cast<std::size_t>(i)].data());
            next += kFramePeriod;
            std::this_thread::sleep_until(next);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(500));  // the last frames encoded
        c.dropped = out.status().front().dropped - dropped0;
        c.encoded = static_cast<std::uint64_t>(frames) - c.dropped;
        c.stationMs = (processCpuMs() - cpu0) / static_cast<double>(std::max<std::uint64_t>(1, c.encoded));
    }
    const H264Settings d{};
    const std::string encoder =
        "x264enc name=counted speed-preset=veryfast tune=zerolatency bitrate=" + std::to_string(d.bitrateKbps) +
        " key-int-max=" + std::to_string(static_cast<int>(d.keyframeSeconds * kFps));
    c.peerMs = pipelineCpuMsPerFrame(testSource(size, total, true) +
                                         " ! videoconvert ! videoscale ! video/x-raw,format=I420," + sizeCaps(size) +
                                         " ! " + encoder + " ! h264parse ! fakesink sync=false",
                                     total);
    c.sourceMs =
        pipelineCpuMsPerFrame(testSource(size, total, true) + " ! identity name=counted ! fakesink sync=false", total);
    return c;
}

struct Latency {
    std::size_t received = 0;
    double medianMs = 0, p95Ms = 0, maxMs = 0;
};

Latency srtLatency(cv::Size size, int frames) {
    const int port = LoopbackUdp().port();
    LaunchedPipeline receiver("srtsrc uri=srt://127.0.0.1:" + std::to_string(port) +
                              "?mode=listener poll-timeout=100 ! tsdemux ! h264parse ! avdec_h264 ! videoconvert ! "
                              "video/x-raw,format=BGR ! appsink name=out sync=false");
    struct Arrivals {
        std::mutex lock;
        std::map<int, Clock::time_point> at;
    } arrivals;
    GstAppSinkCallbacks callbacks{};
    callbacks.new_sample = [](GstAppSink* sink, gpointer data) {
        GstSample* s = gst_app_sink_pull_sample(sink);
        const auto now = Clock::now();
        GstStructure* caps = gst_caps_get_structure(gst_sample_get_caps(s), 0);
        int w = 0, h = 0;
        gst_structure_get_int(caps, "width", &w);
        gst_structure_get_int(caps, "height", &h);
        GstMapInfo map;
        GstBuffer* b = gst_sample_get_buffer(s);
        gst_buffer_map(b, &map, GST_MAP_READ);
        const int n = frameNumberOf(cv::Mat(h, w, CV_8UC3, map.data, GST_ROUND_UP_4(w * 3)));
        gst_buffer_unmap(b, &map);
        gst_sample_unref(s);
        auto* a = static_cast<Arrivals*>(data);
        std::lock_guard lock(a->lock);
        if (n >= 0) a->at.emplace(n, now);
        return GST_FLOW_OK;
    };
    gst_app_sink_set_callbacks(GST_APP_SINK(receiver.element("out")), &callbacks, &arrivals, nullptr);
    receiver.play();

    // Up to 3 s of frames until the caller has connected and the first
    // frame is decoded, 2 s more for what waited meanwhile to drain, then
    // `frames` measured ones.
    const int connecting = 75, draining = 50, trailing = 5;
    std::vector<std::vector<std::uint8_t>> pictures;
    for (int i = 0; i < connecting + draining + frames + trailing; ++i) {
        cv::Mat rgba;
        cv::cvtColor(numberedFrame(i, size), rgba, cv::COLOR_BGR2RGBA);
        pictures.emplace_back(rgba.data, rgba.data + rgba.total() * rgba.elemSize());
    }
    StreamSpec spec = parseStreamUrl("srt://127.0.0.1:" + std::to_string(port));
    spec.name = "latency";
    std::vector<Clock::time_point> pushed;
    int firstMeasured = -1;
    {
        StreamOutputs out({spec}, {size.width, size.height, kFps});
        auto next = Clock::now();
        for (const auto& p : pictures) {
            const int n = static_cast<int>(pushed.size());
            if (firstMeasured < 0) {
                std::lock_guard lock(arrivals.lock);
                if (!arrivals.at.empty() || n == connecting) firstMeasured = n + draining;
            }
            // A few frames after the measured ones: the receiver's demuxer
            // hands a frame on when the next one begins.
            if (firstMeasured >= 0 && n == firstMeasured + frames + trailing) break;
            pushed.push_back(Clock::now());
            out.push(p.data());
            next += kFramePeriod;
            std::this_thread::sleep_until(next);
        }
        std::this_thread::sleep_for(std::chrono::seconds(1));
    }
    std::vector<double> ms;
    std::lock_guard lock(arrivals.lock);
    for (const auto& [n, at] : arrivals.at)
        if (n >= firstMeasured && n < firstMeasured + frames)
            ms.push_back(std::chrono::duration<double, std::milli>(at - pushed[static_cast<std::size_t>(n)]).count());
    Latency l;
    l.received = ms.size();
    l.medianMs = median(ms);
    l.p95Ms = percentile(ms, 95);
    l.maxMs = percentile(ms, 100);
    return l;
}

struct FrameTimes {
    double medianMs = 0, p95Ms = 0;
    std::uint64_t streamDropped = 0;
};

FrameTimes stationFrameTimes(const StationConfig& demo, cv::Size size, int frames,
                             const std::vector<StreamSpec>& streams) {
    StationConfig cfg = demo;
    cfg.compositing.output = {};
    if (size.width > 1000) cfg.compositing.matte.background.scale = 0.25;  // as bench composite's hd part
    for (const StreamSpec& s : streams) cfg.compositing.output.streams.push_back({s, "bench"});
    Station station(cfg, StationInput::fromReplay(std::make_unique<TestPatternSource>(TestPatternOptions{
                                                      .width = size.width, .height = size.height, .paced = false}),
                                                  kFps));
    std::vector<double> ms;
    auto next = Clock::now();
    for (int i = 0; i < kWarmup + frames; ++i) {
        if (!station.frame()) break;
        if (i >= kWarmup) ms.push_back(station.stats().totalMs);
        next += kFramePeriod;
        std::this_thread::sleep_until(next);
    }
    FrameTimes t;
    for (const StreamStatus& s : station.streamStatus()) t.streamDropped += s.dropped;
    station.finish();
    t.medianMs = median(ms);
    t.p95Ms = percentile(ms, 95);
    return t;
}

void writeFrameTimes(BenchJson& j, const char* key, const FrameTimes& t) {
    j.beginObject(key)
        .field("median_ms", Fixed{t.medianMs, 3})
        .field("p95_ms", Fixed{t.p95Ms, 3})
        .field("stream_dropped", t.streamDropped)
        .end();
}

int bench(const StreamBenchOptions& o) {
    if (o.frames < 10) throw InputError("--frames must be >= 10");
    initGstreamer();
    for (const char* e : {"x264enc", "h264parse", "srtsrc", "srtsink", "mpegtsmux", "tsdemux", "avdec_h264",
                          "rtph264pay", "videotestsrc"})
        if (!hasGstElement(e)) throw std::runtime_error(std::string("GStreamer element ") + e + " missing");
    auto context = HeadlessContext::create(GlRequest::Auto);
    const StationConfig demo = loadStationConfig(o.config);

    BenchJson j;
    j.field("bench", "stream").field("frames", o.frames).field("fps", kFps);
    const H264Settings d{};
    j.beginObject("encoding")
        .field("encoder", "x264enc veryfast zerolatency")
        .field("bitrate_kbps", d.bitrateKbps)
        .field("keyframe_seconds", d.keyframeSeconds)
        .end();
    j.beginArray("sizes");
    for (const cv::Size size : {cv::Size(768, 576), cv::Size(1920, 1080)}) {
        std::cerr << "bench stream: " << size.width << "x" << size.height << ": encoder cost, station and peer\n";
        const EncodeCost c = encodeCost(size, o.frames);
        std::cerr << "bench stream: latency over SRT\n";
        const Latency l = srtLatency(size, o.frames);
        std::cerr << "bench stream: the station's frame time without and with each stream\n";
        const FrameTimes none = stationFrameTimes(demo, size, o.frames, {});
        StreamSpec srt = parseStreamUrl("srt://127.0.0.1:" + std::to_string(LoopbackUdp().port()));
        srt.name = "srt";
        LaunchedPipeline srtReceiver("srtsrc uri=srt://127.0.0.1:" + std::to_string(srt.port) +
                                     "?mode=listener poll-timeout=100 ! fakesink sync=false");
        srtReceiver.play();
        const FrameTimes withSrt = stationFrameTimes(demo, size, o.frames, {srt});
        const FrameTimes withRtsp = stationFrameTimes(demo, size, o.frames, {rtspWithoutClients("rtsp")});

        const double peer = c.peerMs - c.sourceMs;
        j.beginObject();
        j.beginArray("size").value(size.width).value(size.height).end();
        j.beginObject("encode_cpu_ms_per_frame")
            .field("station", Fixed{c.stationMs, 3})
            .field("gstreamer_peer", Fixed{peer, 3})
            .field("peer_with_videotestsrc", Fixed{c.peerMs, 3})
            .field("videotestsrc_alone", Fixed{c.sourceMs, 3})
            .field("ratio", Fixed{c.stationMs / peer, 3})
            .field("station_frames_encoded", c.encoded)
            .field("station_frames_dropped", c.dropped)
            .field("within_1_2x", c.stationMs <= 1.2 * peer)
            .end();
        j.beginObject("latency_srt_ms")
            .field("srt_latency_ms", srt.latencyMs)
            .field("frames", l.received)
            .field("median", Fixed{l.medianMs, 3})
            .field("p95", Fixed{l.p95Ms, 3})
            .field("max", Fixed{l.maxMs, 3})
            .end();
        j.beginObject("frame_time");
        writeFrameTimes(j, "no_stream", none);
        writeFrameTimes(j, "srt", withSrt);
        writeFrameTimes(j, "rtsp_no_clients", withRtsp);
        j.end();
        j.end();
    }
    j.end();
    std::printf("%s\n", j.str().c_str());
    return kExitOk;
}

const bool registered = registerCommand(
    {"stream", "Streaming the composite: encoder CPU against GStreamer's own, SRT latency, frame time with streams",
     [](CommandLine& line) {
         auto o = std::make_shared<StreamBenchOptions>();
         line.option("--config", o->config, "the station whose frame time is measured").showDefault();
         line.option("--frames", o->frames, "measured frames per part").showDefault();
         return [o] { return bench(*o); };
     }});

}  // namespace
}  // namespace arcomp
