// arcomp-bench composite: what one composited frame costs, stage by stage,
// headless on this machine, through the same Station that `arcomp replay`
// drives.
//  - vtest: the demo installation (configs/demo-replay.yaml) on vtest.avi at
//    its own size (768x576), writing an MJPG video file as its output.
//    Target: >= 60 fps end to end.
//  - hd: a 1920x1080 MJPG file the benchmark generates from the test
//    pattern, the demo's matte (model at 1/4 scale) and its light CG scene,
//    output read back to the CPU. Targets: >= 30 fps, and >= 1.5x the
//    GStreamer peer's fps measured in the same run.
//  - gstreamer (the hd part's peer, when gst-launch-1.0 is on PATH; else
//    "gstreamer": {"skipped": why} and the ratio target is null): one 1080p
//    stream keyed on green and composited over another, every frame, as
//    fast as it goes:
//      gst-launch-1.0 -q compositor name=mix ! video/x-raw,format=AYUV
//        ! fakesink sync=false
//        videotestsrc num-buffers=N pattern=checkers-8
//        ! video/x-raw,width=1920,height=1080,format=AYUV ! mix.
//        videotestsrc num-buffers=N
//        ! video/x-raw,width=1920,height=1080,format=AYUV
//        ! alpha method=green ! mix.
//    (the SMPTE bars' green bar is keyed out). AYUV throughout is what
//    alpha and compositor work in, so GStreamer converts nothing; left to
//    negotiate, it picks 16-bit ABGR64 and runs at a fraction of this.
//    fps = N / the process's wall time, start-up included, N = warm-up +
//    measured frames (as many as arcomp runs).
//  - holdout: occluders with many triangles (the bunny from
//    ../shared/data/meshes/bunny.obj, else the built-in sphere) in front of the
//    person plane; holdout-mask time with each region's silhouette mesh
//    against the full mesh (the baseline), the camera inside the region.
//    Target: silhouette cheaper.
// --hd-only runs the hd part and its peer alone.
// Stage times are medians over the measured frames (after warm-up); fps is
// measured frames / their wall time. The station is pipelined
// (runtime/station/Station.hpp): capture and matte of frame N+1 run on their own
// thread while frame N renders, so the capture and matte medians overlap the
// others, and a frame is shown one frame later than it would be unpipelined
// ("pipeline_latency": frames, and ms at the measured rate). GL stages are
// the station's own GpuStageTimes: timer queries read a frame late on a GPU;
// on llvmpipe, each stage waited for and timed on the wall clock.

#include "runtime/gl/FrameReadback.hpp"
#include "runtime/gl/GlContext.hpp"
#include "runtime/station/ReplayInput.hpp"
#include "runtime/station/Station.hpp"
#include "tools/bench/probes/ShellCommand.hpp"
#include "tools/bench/report/BenchJson.hpp"
#include "tools/bench/report/Stats.hpp"
#include "tools/cli/Command.hpp"
#include "video/sources/FileSource.hpp"
#include "video/sources/TestPatternSource.hpp"
#include "video/sources/VideoFileWriter.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <optional>

#include <unistd.h>

namespace arcomp {
namespace {

namespace fs = std::filesystem;

struct CompositeOptions {
    std::string config = "configs/demo-replay.yaml";
    std::string model = "../shared/data/meshes/bunny.obj";  // relative to the repository root
    int frames = 100;
    int warmup = 10;
    bool hdOnly = false;
};

struct RunResult {
    std::string source;
    glm::ivec2 size{0};
    int frames = 0;
    double fps = 0;
    FrameStats medians;
    double meanTotal = 0;
    int readbackLatencyFrames = 0;
};

RunResult run(Station& station, const std::string& source, int frames, int warmup, bool readBack = false) {
    std::vector<double> capture, matte, track, update, sel, shadow, render, holdout, composite, output, total;
    std::chrono::steady_clock::time_point measuring;
    // As OutputStage reads: asynchronously on a GPU, into an image kept between frames.
    FrameReadback readback;
    Image img;
    for (int i = 0; i < warmup + frames; ++i) {
        if (i == warmup) measuring = std::chrono::steady_clock::now();
        if (!station.frame()) break;
        FrameStats s = station.stats();
        if (readBack) {
            // What any output needs at least: the frame in CPU memory.
            const auto t0 = std::chrono::steady_clock::now();
            readback.read(station.compositedFrame(), img);
            const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
            s.outputMs += ms;
            s.totalMs += ms;
        }
        if (i < warmup) continue;
        capture.push_back(s.captureMs);
        matte.push_back(s.matteMs);
        track.push_back(s.trackMs);
        update.push_back(s.updateMs);
        sel.push_back(s.selectMs);
        shadow.push_back(s.shadowMs);
        render.push_back(s.renderMs);
        holdout.push_back(s.holdoutMs);
        composite.push_back(s.compositeMs);
        output.push_back(s.outputMs);
        total.push_back(s.totalMs);
    }
    const double wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - measuring).count();
    station.finish();
    RunResult r;
    r.source = source;
    r.size = station.size();
    r.frames = static_cast<int>(total.size());
    double sum = 0;
    for (double t : total) sum += t;
    r.meanTotal = total.empty() ? 0.0 : sum / static_cast<double>(total.size());
    r.fps = total.empty() ? 0.0 : static_cast<double>(total.size()) / wallSeconds;
    r.medians.captureMs = median(capture);
    r.medians.matteMs = median(matte);
    r.medians.trackMs = median(track);
    r.medians.updateMs = median(update);
    r.medians.selectMs = median(sel);
    r.medians.shadowMs = median(shadow);
    r.medians.renderMs = median(render);
    r.medians.holdoutMs = median(holdout);
    r.medians.compositeMs = median(composite);
    r.medians.outputMs = median(output);
    r.medians.totalMs = median(total);
    r.readbackLatencyFrames = readback.latencyFrames();
    r.medians.cgTriangles = station.stats().cgTriangles;
    r.medians.holdoutTriangles = station.stats().holdoutTriangles;
    return r;
}

// One run's fields, into the object `j` has open.
void writeRun(BenchJson& j, const RunResult& r) {
    const FrameStats& m = r.medians;
    j.field("source", r.source);
    j.beginArray("size").value(r.size.x).value(r.size.y).end();
    j.field("frames", r.frames).field("fps", r.fps).field("mean_ms", r.meanTotal);
    j.beginObject("median_ms")
        .field("capture", m.captureMs)
        .field("matte", m.matteMs)
        .field("track", m.trackMs)
        .field("update", m.updateMs)
        .field("select", m.selectMs)
        .field("shadow", m.shadowMs)
        .field("cg_render", m.renderMs)
        .field("holdout", m.holdoutMs)
        .field("composite", m.compositeMs)
        .field("output", m.outputMs)
        .field("total", m.totalMs)
        .end();
    j.field("cg_triangles", m.cgTriangles).field("holdout_triangles", m.holdoutTriangles);
}

fs::path scratchDir() {
    const fs::path d = fs::temp_directory_path() / ("arcomp-bench-composite-" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
}

// Writes `frames` frames of the test pattern at 1920x1080 as MJPG.
fs::path generateHdFile(const fs::path& dir, int frames) {
    const fs::path file = dir / "pattern-1080p.avi";
    TestPatternSource pattern({.width = 1920, .height = 1080, .fps = 30.0, .paced = false});
    VideoFileWriter writer(file.string(), "MJPG", 30.0, {1920, 1080});
    for (int i = 0; i < frames; ++i) writer.write(pattern.render(static_cast<std::uint64_t>(i)));
    writer.close();
    return file;
}

StationConfig occluders(const std::string& model, HoldoutMesh holdout, std::string& used) {
    StationConfig cfg;
    cfg.file = "bench-occluders";
    const bool haveModel = fs::exists(model);
    used = haveModel ? model : "built-in sphere 48x24 (model not found)";
    for (int i = 0; i < 4; ++i) {
        ObjectConfig o;
        o.name = "occluder" + std::to_string(i);
        if (haveModel) {
            o.model = model;
            o.scale = glm::vec3(10.0f);
        } else {
            o.shape = "sphere";
            o.radius = 0.7f;
        }
        o.position = {-2.4f + 1.6f * static_cast<float>(i), -0.8f, -5.0f};
        o.rotationDegrees = {0.0f, 40.0f * static_cast<float>(i), 0.0f};
        cfg.objects.push_back(o);
    }
    cfg.camera.given = true;
    cfg.camera.eye = {0.0f, 0.0f, 0.0f};
    cfg.camera.target = {0.0f, -0.2f, -5.0f};
    cfg.compositing.compositor.personPlaneMetres = 8.0f;
    cfg.compositing.compositor.holdout = holdout;
    return cfg;
}

// The GStreamer peer of the hd part (the pipeline in this file's header):
// fps, or why it did not run.
struct PeerResult {
    std::optional<double> fps;
    double seconds = 0;
    std::string skipped;
};

PeerResult gstreamerPeer(int frames) {
    PeerResult r;
    if (!onPath("gst-launch-1.0")) {
        r.skipped = "gst-launch-1.0 is not on PATH";
        return r;
    }
    const std::string n = std::to_string(frames), caps = "video/x-raw,width=1920,height=1080,format=AYUV";
    const std::string command = "gst-launch-1.0 -q compositor name=mix ! video/x-raw,format=AYUV ! fakesink sync=false"
                                " videotestsrc num-buffers=" +
                                n + " pattern=checkers-8 ! " + caps +
                                " ! mix."
                                " videotestsrc num-buffers=" +
                                n + " ! " + caps + " ! alpha method=green ! mix.";
    const auto t0 = std::chrono::steady_clock::now();
    const ShellResult ran = runShellCommand(command);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (ran.status != 0) {
        r.skipped = "gst-launch-1.0 failed (exit " + std::to_string(ran.status) + "): " + ran.output;
        return r;
    }
    r.fps = static_cast<double>(frames) / r.seconds;
    return r;
}

RunResult runVtest(const StationConfig& demo, const fs::path& scratch, const CompositeOptions& o) {
    StationConfig cfg = demo;
    cfg.compositing.output = {};
    cfg.compositing.output.videoFile = scratch / "vtest-composite.avi";
    std::vector<std::string> warnings;
    StationInput input = openReplayInput(*cfg.compositing.video, warnings);
    for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";
    const std::string source = warnings.empty() ? cfg.compositing.video->path : "test pattern (fallback)";
    std::cerr << "vtest: " << source << "\n";
    Station station(cfg, std::move(input));
    return run(station, source, o.frames, o.warmup);
}

// A generated 1920x1080 file, the demo's matte at 1/4 scale, light CG.
RunResult runHd(const StationConfig& demo, const fs::path& scratch, const CompositeOptions& o) {
    std::cerr << "hd: generating a 1080p MJPG file\n";
    const fs::path file = generateHdFile(scratch, o.warmup + o.frames);
    StationConfig hd = demo;
    hd.compositing.output = {};
    hd.compositing.matte.background.scale = 0.25;
    Station station(hd,
                    StationInput::fromReplay(std::make_unique<FileSource>(FileOptions{.path = file.string()}), 30.0));
    // Read back every frame, as any output would; no encoder on top.
    return run(station, "generated 1920x1080 MJPG", o.frames, o.warmup, true);
}

struct HoldoutResult {
    std::string occluders;
    double silhouetteMs = 0, fullMs = 0, bakeMs = 0;
    std::size_t silhouetteTriangles = 0, fullTriangles = 0, objectsInFront = 0, modelTriangles = 0;
};

// Holdout cost with high-polygon occluders: silhouette vs full mesh.
HoldoutResult runHoldout(const CompositeOptions& o) {
    HoldoutResult r;
    const auto t0 = std::chrono::steady_clock::now();
    Station s(occluders(o.model, HoldoutMesh::Silhouette, r.occluders),
              StationInput::fromReplay(
                  std::make_unique<TestPatternSource>(TestPatternOptions{.width = 768, .height = 576, .paced = false}),
                  30.0));
    r.bakeMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    Station f(occluders(o.model, HoldoutMesh::Full, r.occluders),
              StationInput::fromReplay(
                  std::make_unique<TestPatternSource>(TestPatternOptions{.width = 768, .height = 576, .paced = false}),
                  30.0));
    std::cerr << "holdout: " << r.occluders << "\n";
    // Interleaved so that both see the same machine load.
    std::vector<double> sMs, fMs;
    for (int i = 0; i < o.warmup + o.frames; ++i) {
        s.frame();
        f.frame();
        if (i < o.warmup) continue;
        sMs.push_back(s.stats().holdoutMs);
        fMs.push_back(f.stats().holdoutMs);
    }
    r.silhouetteMs = median(sMs);
    r.fullMs = median(fMs);
    r.silhouetteTriangles = s.stats().holdoutTriangles;
    r.fullTriangles = f.stats().holdoutTriangles;
    r.objectsInFront = s.stats().objectsInFront;
    r.modelTriangles = f.stats().cgTriangles;
    return r;
}

int bench(const CompositeOptions& o) {
    if (o.frames < 1 || o.warmup < 0) throw InputError("--frames must be >= 1 and --warmup >= 0");
    auto context = HeadlessContext::create(GlRequest::Auto);
    const fs::path scratch = scratchDir();
    const StationConfig demo = loadStationConfig(o.config);
    if (!demo.compositing.video) throw InputError(o.config + ": no video section");

    std::optional<RunResult> vtest;
    if (!o.hdOnly) vtest = runVtest(demo, scratch, o);
    const RunResult hd = runHd(demo, scratch, o);
    std::cerr << "hd: the GStreamer peer\n";
    const PeerResult gst = gstreamerPeer(o.warmup + o.frames);
    std::optional<HoldoutResult> holdout;
    if (!o.hdOnly) holdout = runHoldout(o);
    std::error_code ec;
    fs::remove_all(scratch, ec);

    BenchJson j;
    j.field("bench", "composite").field("gl", toString(context->api()));
    if (vtest) {
        j.beginObject("vtest");
        writeRun(j, *vtest);
        j.end();
    }
    j.beginObject("hd");
    writeRun(j, hd);
    // What the pipelining adds: the frame is shown one station frame later,
    // and read back one more later where the readback is asynchronous.
    const int latency = 1 + hd.readbackLatencyFrames;
    j.beginObject("pipeline_latency")
        .field("frames", latency)
        .field("ms", hd.fps > 0 ? latency * 1000.0 / hd.fps : 0.0)
        .field("readback", hd.readbackLatencyFrames ? "asynchronous" : "synchronous")
        .end();
    j.end().field("hd_matte_scale", 0.25);
    j.beginObject("gstreamer");
    if (gst.fps) {
        j.field("fps", *gst.fps).field("frames", o.warmup + o.frames).field("seconds", gst.seconds);
        j.field("hd_fps_ratio", hd.fps / *gst.fps);
    } else {
        j.field("skipped", gst.skipped);
    }
    j.end();
    if (holdout)
        j.beginObject("holdout")
            .field("occluders", holdout->occluders)
            .field("objects_in_front", holdout->objectsInFront)
            .field("cg_triangles", holdout->modelTriangles)
            .field("silhouette_ms", holdout->silhouetteMs)
            .field("full_ms", holdout->fullMs)
            .field("silhouette_triangles", holdout->silhouetteTriangles)
            .field("full_triangles", holdout->fullTriangles)
            .field("setup_with_bake_ms", holdout->bakeMs)
            .end();

    // A target whose part did not run is null, and does not count.
    bool met = true;
    j.beginObject("targets");
    const auto target = [&](const char* name, std::optional<bool> ok) {
        if (!ok) {
            j.null(name);
            return;
        }
        j.field(name, *ok);
        met = met && *ok;
    };
    target("vtest_60fps", vtest ? std::optional<bool>(vtest->fps >= 60.0) : std::nullopt);
    target("hd_30fps", hd.fps >= 30.0);
    target("hd_1_5x_gstreamer", gst.fps ? std::optional<bool>(hd.fps >= 1.5 * *gst.fps) : std::nullopt);
    target("silhouette_cheaper", holdout ? std::optional<bool>(holdout->silhouetteMs < holdout->fullMs) : std::nullopt);
    j.end();
    j.field("targets_met", met);
    std::cout << j.str() << "\n";
    return kExitOk;
}

const bool registered =
    registerCommand({"composite", "Compositing: per-stage ms, fps at 768x576 and 1080p, silhouette vs full holdout",
                     [](CommandLine& line) {
                         auto o = std::make_shared<CompositeOptions>();
                         line.option("--config", o->config, "station config for the vtest run").showDefault();
                         line.option("--model", o->model, "high-polygon occluder model").showDefault();
                         line.option("--frames", o->frames, "measured frames per run").showDefault();
                         line.option("--warmup", o->warmup, "frames before measuring").showDefault();
                         line.flag("--hd-only", o->hdOnly, "only the 1080p part and its GStreamer peer");
                         return [o] { return bench(*o); };
                     }});

}  // namespace
}  // namespace arcomp
