// `arcomp-bench budget`: the uniform-frame-time paper's flight test
// (DESIGN.md §3, its Fig. 3 and 4). A camera flies a fixed path over a field
// of mountains; every frame is drawn at 1280x720, first unmanaged (finest
// level, Phong, like the paper's "no simplification"), then managed by the
// frame-time controller with target T, in the same process. The baseline is
// the unmanaged run.
//
//   arcomp-bench budget --out build/bench-budget [--target-ms T] [--frames 600]
//
// Frame time is what the timer (runtime/gl/FrameTimer.hpp) gives for the
// draw, clear to glFinish; select and the controller's own CPU time are
// reported apart (apply_us). The cost model is calibrated in the same run
// (or read with --calibration) and re-fitted online during the managed run.
//
// The default target is 0.85 of the unmanaged run's fastest frame: full
// detail exceeds it on the whole path, so the controller has work to do
// everywhere, and the figure follows the machine's speed on the day (on
// this shared host the same run varies by 2× from hour to hour, so no fixed
// number is "most frames" every time). The margin is for the machine's
// speed drifting between the two runs: with the unmanaged run's 3rd
// percentile as the target, one managed run drew the path's cheapest
// stretch (frames 232-267) at full detail in 22-25 ms where the unmanaged
// run had taken 29-31, under a target of 29.4 that nothing could then
// meet, and 68 frames fell outside ±10%. It is never set below the
// controller's floor along the path (every object at its coarsest level and
// unlit; the pixels seen close up cost that much whatever is drawn), which
// the JSON reports as floor_ms_max_estimate: the calibrated floor scaled by
// the table's error in the unmanaged run.
//
// llvmpipe's raster threads share the two cores with the thread that
// issues the draws, so a frame's time depends on how the two are scheduled
// against each other and against the machine's other work. With two raster
// threads the same frame drawn again varied by +14% at the 95th percentile,
// more than the ±10% band the controller is judged by; with one, +4..9% on
// a quiet machine, and p95 |dev| from the target was 10.0-14.2% in six runs
// (met once in nineteen over two sessions). --raster-threads 0 (the
// default) has llvmpipe rasterize on the thread that draws: frames take
// 1.5-1.9x as long (nothing overlaps), the table's one-step error at the
// 95th percentile fell from 8.8% to 6.1%, and the floor fell from about
// 0.8 of the target to 0.6, which leaves the controller more room. -1
// leaves the driver's choice. Since the station keeps the memory a frame
// frees (runtime/app/ResidentHeap.hpp), frames here take a quarter of the time
// they did (targets near 37 ms, not 140), so the same jitter in ms is a
// larger share of the target, and the floor is often nearer it again
// (0.5-0.9 of it in fourteen runs). The JSON reports the platform's own
// noise as repeat_jitter_p95_pct: one view at full detail, drawn 60 times.
// Other drivers ignore LP_NUM_THREADS.
//
// Writes to --out: budget_frames.csv (per frame), budget_items.csv (per
// drawn item: its setting, pixels and calibrated cost, to study the model's
// error offline), budget_frame_time.png
// (unmanaged, managed, target), budget_prediction.png (managed predicted vs
// measured) and calibration.yaml.

#include "graph/budget/FrameBudget.hpp"
#include "graph/budget/OnScreenPixels.hpp"
#include "graph/core/SelectPass.hpp"
#include "graph/lod/LodAlternatives.hpp"
#include "runtime/config/CalibrationFile.hpp"
#include "runtime/gl/GlContext.hpp"
#include "runtime/gl/RenderTarget.hpp"
#include "tools/bench/probes/CostCalibration.hpp"
#include "tools/bench/report/BenchJson.hpp"
#include "tools/bench/report/LinePlot.hpp"
#include "tools/bench/report/Stats.hpp"
#include "tools/bench/scenes/FlightScene.hpp"
#include "tools/cli/CliParse.hpp"
#include "tools/cli/Command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <numeric>

namespace arcomp {

namespace {

struct Options {
    std::string out = "bench-budget";
    std::string size = "1280x720";
    std::string timer = "finish";
    std::string calibration;
    double targetMs = 0.0;  // 0: kTargetUnderFastest of the unmanaged run's fastest frame
    int rasterThreads = 0;  // LP_NUM_THREADS (0: on the drawing thread); -1: the driver's default
    BudgetSettings controller{};
    int frames = 600;
    int mountains = 60;
    int sceneFrames = 150;
};

const glm::vec4 kSky(0.55f, 0.68f, 0.85f, 1.0f);
constexpr double kTargetUnderFastest = 0.85;

struct Series {
    std::vector<double> ms, predicted, quality, applyUs, gain;  // gain: the online fit's, as predicted
    std::vector<double> itemsMs, floorItemsMs;                  // calibrated: as drawn, all coarsest and unlit
    std::vector<std::size_t> items, reduced;
};

double stddev(const std::vector<double>& v) {
    if (v.size() < 2) return 0.0;
    const double mean = std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
    double s = 0.0;
    for (double x : v) s += (x - mean) * (x - mean);
    return std::sqrt(s / static_cast<double>(v.size() - 1));
}

// A run's frame-time fields, into the object `j` has open.
void writeFrameStats(BenchJson& j, const std::vector<double>& ms) {
    const double lo = *std::min_element(ms.begin(), ms.end()), hi = *std::max_element(ms.begin(), ms.end());
    j.field("frame_ms_median", median(ms))
        .field("frame_ms_p95", percentile(ms, 95))
        .field("frame_ms_max", hi)
        .field("frame_ms_min", lo)
        .field("frame_ms_stddev", stddev(ms))
        .field("max_min_ratio", lo > 0 ? hi / lo : 0.0);
}

// Flies the path once; with a budget, each frame goes through it.
Series fly(FlightScene& flight, Renderer& renderer, FrameTimer& timer, int frames, glm::ivec2 size,
           const CostModel& table, FrameBudget* budget, std::ostream& itemsCsv) {
    const char* run = budget ? "managed" : "unmanaged";
    Series s;
    DrawList list;
    const LodAlternatives alternatives(flight.world.scene);
    for (int f = 0; f < frames; ++f) {
        const View view = flightView(frames > 1 ? f / double(frames - 1) : 0.0, size);
        select(flight.world, view, {.shading = Shading::Phong}, list);
        double floorItems = 0.0;
        for (const DrawItem& item : list.items)
            floorItems += table.itemMs(alternatives.levelCount(item.node) - 1u, Shading::Unlit,
                                       onScreenPixels(item, flight.world.scene, view));
        s.floorItemsMs.push_back(floorItems);
        s.itemsMs.push_back(table.itemsMs(list, flight.world.scene, view));
        double predicted = table.frameMs(s.itemsMs.back());
        double quality = 1.0;
        std::size_t reduced = 0;
        if (budget) {
            const auto t0 = std::chrono::steady_clock::now();
            const BudgetStats st = budget->apply(flight.world.scene, list, view);
            s.applyUs.push_back(
                std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
            predicted = st.predictedMs;
            quality = st.quality;
            reduced = st.itemsReduced;
            s.gain.push_back(budget->model().gain());
        }
        for (const DrawItem& item : list.items) {
            const float px = onScreenPixels(item, flight.world.scene, view);
            itemsCsv << run << ',' << f << ',' << alternatives.object(item.node) << ',' << int(item.level) << ','
                     << int(item.shading) << ',' << px << ',' << table.itemMs(item.level, item.shading, px) << '\n';
        }
        timer.begin();
        renderer.draw(flight.world.scene, list, view, {.clearColor = kSky});
        const double ms = timer.end();
        if (budget) budget->observe(ms);
        s.ms.push_back(ms);
        s.predicted.push_back(predicted);
        s.quality.push_back(quality);
        s.items.push_back(list.items.size());
        s.reduced.push_back(reduced);
        if (f % 100 == 0) std::cerr << (budget ? "managed" : "unmanaged") << " frame " << f << ": " << ms << " ms\n";
    }
    return s;
}

// The platform's own noise: one view at full detail drawn again and again;
// how far the 95th percentile lies above the median, in percent.
double repeatJitterPct(FlightScene& flight, Renderer& renderer, FrameTimer& timer, glm::ivec2 size) {
    DrawList list;
    const View view = flightView(0.0, size);
    select(flight.world, view, {.shading = Shading::Phong}, list);
    std::vector<double> ms;
    for (int k = 0; k < 60; ++k) {
        timer.begin();
        renderer.draw(flight.world.scene, list, view, {.clearColor = kSky});
        ms.push_back(timer.end());
    }
    const double middle = median(ms);
    return middle > 0.0 ? 100.0 * (percentile(ms, 95) / middle - 1.0) : 0.0;
}

std::vector<double> frameAxis(std::size_t n) {
    std::vector<double> x(n);
    std::iota(x.begin(), x.end(), 0.0);
    return x;
}

int run(const Options& o) {
    const glm::ivec2 size = parseSize(o.size, "--size");
    if (o.frames < 2 || o.frames > 100000) throw InputError("--frames must lie in 2..100000");
    if (o.mountains < 1 || o.mountains > 10000) throw InputError("--mountains must lie in 1..10000");
    if (!(o.targetMs >= 0.0)) throw InputError("--target-ms must be positive, or 0 for the default");
    if (o.rasterThreads < -1 || o.rasterThreads > 64)
        throw InputError("--raster-threads must lie in 0..64, or be -1 for the driver's default");
    if (!(o.controller.upgradeMargin >= 0.0 && o.controller.upgradeMargin <= 0.5))
        throw InputError("--upgrade-margin must lie in 0..0.5");
    if (o.controller.holdFrames < 0 || o.controller.holdFrames > 10000)
        throw InputError("--hold-frames must lie in 0..10000");
    const TimerMode timerMode = parseTimerMode(o.timer, "--timer");
    const std::filesystem::path out(o.out);
    std::filesystem::create_directories(out);

    FlightScene flight = buildFlightScene({.mountains = o.mountains});
    // llvmpipe reads it when the context is made.
    if (o.rasterThreads >= 0) setenv("LP_NUM_THREADS", std::to_string(o.rasterThreads).c_str(), 1);
    auto context = HeadlessContext::create(GlRequest::Auto);
    RenderTarget target(size);
    target.bind();
    Renderer renderer;
    FrameTimer timer(timerMode);

    // Every level of every mountain reaches the GPU before anything is timed.
    {
        DrawList all;
        for (const auto& levels : flight.mountains)
            for (NodeId n : levels)
                all.items.push_back({n, flight.world.scene.meshPart(n), 1.0f, 1.0f, 0, Shading::Phong});
        const View v = View::framing(flight.world.scene.bound(), 45.0f, size);
        renderer.draw(flight.world.scene, all, v);
        timer.begin();
        timer.end();
    }

    CostModel table;
    double calibrationSeconds = 0.0;
    if (!o.calibration.empty()) {
        table = readCalibration(o.calibration);
    } else {
        const auto t0 = std::chrono::steady_clock::now();
        CalibrationOptions options;
        options.viewport = size;
        table = calibrateCosts(flight.world.scene, flight.mountains[0], renderer, timer, options);
        // Then whole frames from views along the path, every object at a
        // random setting: occlusion and the scene's real mix enter the fit.
        std::vector<View> views;
        std::vector<DrawList> lists;
        for (int k = 0; k < 24; ++k) {
            views.push_back(flightView((k + 0.5) / 24.0, size));
            lists.emplace_back();
            select(flight.world, views.back(), {.shading = Shading::Phong}, lists.back());
        }
        table = fitCostsOnFrames(flight.world.scene, lists, views, renderer, timer, table, o.sceneFrames, options);
        calibrationSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        writeCalibration(out / "calibration.yaml", table, {glDescription(), size});
    }

    const double jitterPct = repeatJitterPct(flight, renderer, timer, size);
    std::cerr << "unmanaged run, " << o.frames << " frames\n";
    CostModel tableOnly = table;
    tableOnly.enableRefit(false);
    std::ofstream itemsCsv(out / "budget_items.csv");
    itemsCsv << "run,frame,object,level,shading,pixels,table_ms\n";
    const Series unmanaged = fly(flight, renderer, timer, o.frames, size, tableOnly, nullptr, itemsCsv);
    // The table's error on this machine now: the median of measured over
    // predicted items time in the unmanaged run.
    std::vector<double> tableGain;
    for (std::size_t f = 0; f < unmanaged.ms.size(); ++f)
        if (unmanaged.itemsMs[f] > 0.0)
            tableGain.push_back((unmanaged.ms[f] - table.overheadMs) / unmanaged.itemsMs[f]);
    const double gainU = tableGain.empty() ? 1.0 : std::max(0.25, median(tableGain));
    double floorMs = 0.0;
    for (double items : unmanaged.floorItemsMs) floorMs = std::max(floorMs, gainU * items + table.overheadMs);
    const double unmanagedFastest = *std::min_element(unmanaged.ms.begin(), unmanaged.ms.end());
    const double underFastest = kTargetUnderFastest * unmanagedFastest;
    const double targetMs = o.targetMs > 0.0 ? o.targetMs : std::max(underFastest, floorMs);
    const char* targetRule = o.targetMs > 0.0 ? "given" : underFastest >= floorMs ? "under_unmanaged_fastest" : "floor";

    std::cerr << "managed run, target " << targetMs << " ms\n";
    BudgetSettings settings = o.controller;
    settings.targetMs = targetMs;
    FrameBudget budget(table, settings);
    const Series managed = fly(flight, renderer, timer, o.frames, size, tableOnly, &budget, itemsCsv);
    if (!itemsCsv) throw std::runtime_error((out / "budget_items.csv").string() + ": write failed");

    // Managed-run figures.
    // absDev: what a viewer sees. predictedDev: where the controller put the
    // frame by its own model; the gap between the two is the model's error
    // and the machine's jitter (on a shared machine, mostly the latter).
    std::vector<double> absDev, predictedDev, predictionError;
    std::size_t over20 = 0, unmanagedOver = 0;
    double qualityArea = 0.0;
    for (std::size_t f = 0; f < managed.ms.size(); ++f) {
        absDev.push_back(100.0 * std::abs(managed.ms[f] - targetMs) / targetMs);
        predictedDev.push_back(100.0 * std::abs(managed.predicted[f] - targetMs) / targetMs);
        predictionError.push_back(100.0 * std::abs(managed.predicted[f] - managed.ms[f]) / managed.ms[f]);
        over20 += managed.ms[f] > 1.2 * targetMs;
        unmanagedOver += unmanaged.ms[f] > targetMs;
        qualityArea += managed.quality[f];
    }
    std::vector<double> unmanagedPredictionError;
    for (std::size_t f = 0; f < unmanaged.ms.size(); ++f)
        unmanagedPredictionError.push_back(100.0 * std::abs(unmanaged.predicted[f] - unmanaged.ms[f]) /
                                           unmanaged.ms[f]);
    const double n = static_cast<double>(managed.ms.size());
    const double p95Dev = percentile(absDev, 95), over20Pct = 100.0 * static_cast<double>(over20) / n;
    const double predErr = median(predictionError);
    const double ratio = *std::max_element(unmanaged.ms.begin(), unmanaged.ms.end()) / unmanagedFastest;

    {
        std::ofstream csv(out / "budget_frames.csv");
        csv << "frame,target_ms,unmanaged_ms,unmanaged_predicted_ms,managed_ms,managed_predicted_ms,managed_quality,"
               "items,items_reduced,apply_us,managed_gain\n";
        for (std::size_t f = 0; f < managed.ms.size(); ++f)
            csv << f << ',' << targetMs << ',' << unmanaged.ms[f] << ',' << unmanaged.predicted[f] << ','
                << managed.ms[f] << ',' << managed.predicted[f] << ',' << managed.quality[f] << ',' << managed.items[f]
                << ',' << managed.reduced[f] << ',' << managed.applyUs[f] << ',' << managed.gain[f] << '\n';
        if (!csv) throw std::runtime_error((out / "budget_frames.csv").string() + ": write failed");
    }
    const std::vector<double> x = frameAxis(managed.ms.size());
    LinePlot times("frame time along the flight path (paper Fig. 3 and 4)", "frame", "ms");
    times.addSeries("unmanaged (finest level, Phong)", x, unmanaged.ms);
    times.addSeries("managed", x, managed.ms);
    times.addLevel("target", targetMs);
    times.writePng(out / "budget_frame_time.png");
    LinePlot prediction("managed run: predicted vs measured frame time", "frame", "ms");
    prediction.addSeries("measured", x, managed.ms);
    prediction.addSeries("predicted", x, managed.predicted);
    prediction.addLevel("target", targetMs);
    prediction.writePng(out / "budget_prediction.png");

    const bool met = p95Dev <= 10.0 && over20Pct <= 1.0 && predErr <= 10.0 && ratio >= 3.0;
    BenchJson json;
    json.field("bench", "budget")
        .field("device", glDescription())
        .field("timer", timer.method())
        .field("raster_threads", o.rasterThreads)
        .field("repeat_jitter_p95_pct", jitterPct);
    json.beginArray("size").value(size.x).value(size.y).end();
    json.field("frames", o.frames).field("mountains", o.mountains);
    json.beginArray("triangles_per_level");
    for (const std::size_t triangles : flight.trianglesPerLevel) json.value(triangles);
    json.end();
    json.field("calibration_s", calibrationSeconds)
        .field("target_ms", targetMs)
        .field("target_rule", targetRule)
        .field("floor_ms_max_estimate", floorMs);
    json.beginObject("unmanaged");
    writeFrameStats(json, unmanaged.ms);
    json.field("frames_over_target_pct", 100.0 * static_cast<double>(unmanagedOver) / n)
        .field("prediction_error_pct_median", median(unmanagedPredictionError))
        .end();
    json.beginObject("managed");
    writeFrameStats(json, managed.ms);
    json.field("p95_abs_dev_from_target_pct", p95Dev)
        .field("frames_over_target_by_20pct_pct", over20Pct)
        .field("predicted_p95_abs_dev_from_target_pct", percentile(predictedDev, 95))
        .field("mean_quality", qualityArea / n)
        .field("prediction_error_pct_median", predErr)
        .field("apply_us_median", median(managed.applyUs))
        .field("final_gain", budget.model().gain())
        .field("final_offset_ms", budget.model().offset())
        .end();
    json.field("targets_met", met).field("out", out.string());
    std::cout << json.str() << std::endl;
    return kExitOk;
}

const bool registered = registerCommand(
    {"budget", "Uniform frame time: a flight over mountains, unmanaged vs the frame-time controller",
     [](CommandLine& line) {
         auto o = std::make_shared<Options>();
         line.option("--out", o->out, "folder for the CSV, the plots and calibration.yaml").showDefault();
         line.option("--target-ms", o->targetMs,
                     "target frame time; 0: " + std::to_string(kTargetUnderFastest).substr(0, 4) +
                         " of the unmanaged run's fastest frame (not below the floor)")
             .showDefault();
         line.option("--raster-threads", o->rasterThreads,
                     "llvmpipe raster threads (LP_NUM_THREADS); 0: on the drawing thread; -1: the driver's default")
             .showDefault();
         line.option("--upgrade-margin", o->controller.upgradeMargin,
                     "hysteresis: a raise must leave this fraction of the target unused")
             .showDefault();
         line.option("--hold-frames", o->controller.holdFrames, "hysteresis: frames a lowered object stays down")
             .showDefault();
         line.option("--frames", o->frames, "frames along the path, per run").showDefault();
         line.option("--mountains", o->mountains, "mountains in the field").showDefault();
         line.option("--size", o->size, "output size WIDTHxHEIGHT").showDefault();
         line.option("--timer", o->timer, kTimerModeHelp).showDefault();
         line.option("--scene-frames", o->sceneFrames, "whole frames of the flight scene in the calibration")
             .showDefault();
         line.option("--calibration", o->calibration, "read this calibration instead of measuring one");
         return [o] { return run(*o); };
     }});

}  // namespace

}  // namespace arcomp
