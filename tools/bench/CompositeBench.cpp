// arcomp bench composite: what one composited frame costs, stage by stage,
// headless on this machine, through the same Station that `arcomp replay`
// drives.
//  - vtest: the demo installation (configs/demo-replay.yaml) on vtest.avi at
//    its own size (768x576), writing an MJPG video file as its output.
//    Target: >= 60 fps end to end.
//  - hd: a 1920x1080 MJPG file the benchmark generates from the test
//    pattern, the demo's matte (model at 1/4 scale) and its light CG scene,
//    output read back to the CPU. Target: >= 30 fps.
//  - holdout: occluders with many triangles (the bunny from
//    ../shared/data/meshes/bunny.obj, else the built-in sphere) in front of the
//    person plane; holdout-mask time with each region's silhouette mesh
//    against the full mesh (the baseline), the camera inside the region.
//    Target: silhouette cheaper.
// Stage times are medians over the measured frames (after warm-up); fps is
// 1000 / mean total. GL stages are the station's own GpuStageTimes: timer
// queries read a frame late on a GPU; on llvmpipe, each stage waited for and
// timed on the wall clock.

#include "runtime/GlContext.hpp"
#include "runtime/ReplayInput.hpp"
#include "runtime/Station.hpp"
#include "tools/arcomp/Command.hpp"
#include "tools/bench/BenchJson.hpp"
#include "tools/bench/Stats.hpp"
#include "video/FileSource.hpp"
#include "video/TestPatternSource.hpp"
#include "video/VideoFileWriter.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>

#include <unistd.h>

namespace arcomp {
namespace {

namespace fs = std::filesystem;

struct CompositeOptions {
    std::string config = "configs/demo-replay.yaml";
    std::string model = "../shared/data/meshes/bunny.obj";  // relative to the repository root
    int frames = 100;
    int warmup = 10;
};

struct RunResult {
    std::string source;
    glm::ivec2 size{0};
    int frames = 0;
    double fps = 0;
    FrameStats medians;
    double meanTotal = 0;
};

RunResult run(Station& station, const std::string& source, int frames, int warmup, bool readBack = false) {
    std::vector<double> capture, matte, update, sel, render, holdout, composite, output, total;
    for (int i = 0; i < warmup + frames; ++i) {
        if (!station.frame()) break;
        FrameStats s = station.stats();
        if (readBack) {
            // What any output needs at least: the frame in CPU memory.
            const auto t0 = std::chrono::steady_clock::now();
            const Image img = station.compositedFrame().read();
            const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
            s.outputMs += ms;
            s.totalMs += ms;
        }
        if (i < warmup) continue;
        capture.push_back(s.captureMs);
        matte.push_back(s.matteMs);
        update.push_back(s.updateMs);
        sel.push_back(s.selectMs);
        render.push_back(s.renderMs);
        holdout.push_back(s.holdoutMs);
        composite.push_back(s.compositeMs);
        output.push_back(s.outputMs);
        total.push_back(s.totalMs);
    }
    station.finish();
    RunResult r;
    r.source = source;
    r.size = station.size();
    r.frames = static_cast<int>(total.size());
    double sum = 0;
    for (double t : total) sum += t;
    r.meanTotal = total.empty() ? 0.0 : sum / static_cast<double>(total.size());
    r.fps = r.meanTotal > 0 ? 1000.0 / r.meanTotal : 0.0;
    r.medians.captureMs = median(capture);
    r.medians.matteMs = median(matte);
    r.medians.updateMs = median(update);
    r.medians.selectMs = median(sel);
    r.medians.renderMs = median(render);
    r.medians.holdoutMs = median(holdout);
    r.medians.compositeMs = median(composite);
    r.medians.outputMs = median(output);
    r.medians.totalMs = median(total);
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
        .field("update", m.updateMs)
        .field("select", m.selectMs)
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

int bench(const CompositeOptions& o) {
    if (o.frames < 1 || o.warmup < 0) throw InputError("--frames must be >= 1 and --warmup >= 0");
    auto context = HeadlessContext::create(GlRequest::Auto);
    const fs::path scratch = scratchDir();

    // 1. The demo installation on vtest.avi.
    StationConfig demo = loadStationConfig(o.config);
    if (!demo.compositing.video) throw InputError(o.config + ": no video section");
    demo.compositing.output = {};
    demo.compositing.output.videoFile = scratch / "vtest-composite.avi";
    std::vector<std::string> warnings;
    StationInput vtestInput = openReplayInput(*demo.compositing.video, warnings);
    for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";
    const std::string vtestSource = warnings.empty() ? demo.compositing.video->path : "test pattern (fallback)";
    std::cerr << "vtest: " << vtestSource << "\n";
    RunResult vtest;
    {
        Station station(demo, std::move(vtestInput));
        vtest = run(station, vtestSource, o.frames, o.warmup);
    }

    // 2. A generated 1920x1080 file, the demo's matte at 1/4 scale, light CG.
    std::cerr << "hd: generating a 1080p MJPG file\n";
    const fs::path hdFile = generateHdFile(scratch, o.warmup + o.frames);
    StationConfig hd = demo;
    hd.compositing.output = {};
    hd.compositing.matte.background.scale = 0.25;
    RunResult hdRun;
    {
        Station station(hd, StationInput::fromReplay(std::make_unique<FileSource>(FileOptions{.path = hdFile.string()}), 30.0));
        // Read back every frame, as any output would; no encoder on top.
        hdRun = run(station, "generated 1920x1080 MJPG", o.frames, o.warmup, true);
    }

    // 3. Holdout cost with high-polygon occluders: silhouette vs full mesh.
    std::string used;
    RunResult sil, full;
    double bakeMs = 0;
    std::size_t modelTriangles = 0;
    {
        const auto t0 = std::chrono::steady_clock::now();
        Station s(occluders(o.model, HoldoutMesh::Silhouette, used), StationInput::fromReplay(
            std::make_unique<TestPatternSource>(TestPatternOptions{.width = 768, .height = 576, .paced = false}), 30.0));
        bakeMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        Station f(occluders(o.model, HoldoutMesh::Full, used), StationInput::fromReplay(
            std::make_unique<TestPatternSource>(TestPatternOptions{.width = 768, .height = 576, .paced = false}), 30.0));
        std::cerr << "holdout: " << used << "\n";
        // Interleaved so that both see the same machine load.
        std::vector<double> sMs, fMs;
        for (int i = 0; i < o.warmup + o.frames; ++i) {
            s.frame();
            f.frame();
            if (i < o.warmup) continue;
            sMs.push_back(s.stats().holdoutMs);
            fMs.push_back(f.stats().holdoutMs);
        }
        sil.medians.holdoutMs = median(sMs);
        full.medians.holdoutMs = median(fMs);
        sil.medians.holdoutTriangles = s.stats().holdoutTriangles;
        full.medians.holdoutTriangles = f.stats().holdoutTriangles;
        sil.medians.objectsInFront = s.stats().objectsInFront;
        modelTriangles = f.stats().cgTriangles;
    }
    std::error_code ec;
    fs::remove_all(scratch, ec);

    const bool vtestOk = vtest.fps >= 60.0, hdOk = hdRun.fps >= 30.0,
               holdoutOk = sil.medians.holdoutMs < full.medians.holdoutMs;
    BenchJson j;
    j.field("bench", "composite").field("gl", toString(context->api()));
    j.beginObject("vtest");
    writeRun(j, vtest);
    j.end().beginObject("hd");
    writeRun(j, hdRun);
    j.end().field("hd_matte_scale", 0.25);
    j.beginObject("holdout")
        .field("occluders", used)
        .field("objects_in_front", sil.medians.objectsInFront)
        .field("cg_triangles", modelTriangles)
        .field("silhouette_ms", sil.medians.holdoutMs)
        .field("full_ms", full.medians.holdoutMs)
        .field("silhouette_triangles", sil.medians.holdoutTriangles)
        .field("full_triangles", full.medians.holdoutTriangles)
        .field("setup_with_bake_ms", bakeMs)
        .end();
    j.beginObject("targets").field("vtest_60fps", vtestOk).field("hd_30fps", hdOk).field("silhouette_cheaper", holdoutOk).end();
    j.field("targets_met", vtestOk && hdOk && holdoutOk);
    std::cout << j.str() << "\n";
    return kExitOk;
}

const bool registered = registerBench({"composite", "Compositing: per-stage ms, fps at 768x576 and 1080p, silhouette vs full holdout",
    [](CommandLine& line) {
        auto o = std::make_shared<CompositeOptions>();
        line.option("--config", o->config, "station config for the vtest run").showDefault();
        line.option("--model", o->model, "high-polygon occluder model").showDefault();
        line.option("--frames", o->frames, "measured frames per run").showDefault();
        line.option("--warmup", o->warmup, "frames before measuring").showDefault();
        return [o] { return bench(*o); };
    }});

} // namespace
} // namespace arcomp
