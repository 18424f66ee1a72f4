// `arcomp-bench calibrate`: measures the frame-time cost model (A and B per
// LOD level and shading, and the frame overhead; DESIGN.md §3) for the
// flight scene's mountain on this machine and writes the calibration file a
// station's `budget.calibration` names.
//
//   arcomp-bench calibrate --out build/bench-budget   # writes calibration.yaml

#include "runtime/config/CalibrationFile.hpp"
#include "runtime/gl/GlContext.hpp"
#include "runtime/gl/RenderTarget.hpp"
#include "tools/bench/probes/CostCalibration.hpp"
#include "tools/bench/report/BenchJson.hpp"
#include "tools/bench/scenes/FlightScene.hpp"
#include "tools/cli/CliParse.hpp"
#include "tools/cli/Command.hpp"

#include <chrono>
#include <iostream>
#include <memory>

namespace arcomp {

namespace {

struct Options {
    std::string out = "bench-budget";
    std::string size = "1280x720";
    std::string timer = "finish";
    int repeats = 5;
};

int run(const Options& o) {
    const glm::ivec2 size = parseSize(o.size, "--size");
    if (o.repeats < 1 || o.repeats > 100) throw InputError("--repeats must lie in 1..100");
    const TimerMode timerMode = parseTimerMode(o.timer, "--timer");
    const FlightScene flight = buildFlightScene({.mountains = 1});
    auto context = HeadlessContext::create(GlRequest::Auto);
    RenderTarget target(size);
    target.bind();
    Renderer renderer;
    FrameTimer timer(timerMode);
    const auto t0 = std::chrono::steady_clock::now();
    CalibrationOptions options;
    options.viewport = size;
    options.repeats = o.repeats;
    const CostModel model = calibrateCosts(flight.world.scene, flight.mountains[0], renderer, timer, options);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const auto file = std::filesystem::path(o.out) / "calibration.yaml";
    writeCalibration(file, model, {glDescription(), size});
    std::cerr << "wrote " << file.string() << "\n";

    BenchJson json;
    json.field("bench", "calibrate").field("device", glDescription()).field("timer", timer.method());
    json.beginArray("size").value(size.x).value(size.y).end();
    json.field("seconds", seconds).field("overhead_ms", model.overheadMs);
    json.beginArray("levels");
    for (std::size_t l = 0; l < model.levels(); ++l) {
        json.beginObject().field("triangles", flight.trianglesPerLevel[l]);
        for (int s = 0; s < kShadingCount; ++s) {
            const CostCoefficients& c = model.at(l, static_cast<Shading>(s));
            json.beginArray(toString(static_cast<Shading>(s))).value(c.msPerPixel).value(c.ms).end();
        }
        json.end();
    }
    json.end().field("file", file.string());
    std::cout << json.str() << std::endl;
    return kExitOk;
}

const bool registered = registerCommand(
    {"calibrate", "Measure the frame-time cost model (A, B per level and shading) and write calibration.yaml",
     [](CommandLine& line) {
         auto o = std::make_shared<Options>();
         line.option("--out", o->out, "folder for calibration.yaml").showDefault();
         line.option("--size", o->size, "output size WIDTHxHEIGHT").showDefault();
         line.option("--timer", o->timer, kTimerModeHelp).showDefault();
         line.option("--repeats", o->repeats, "frames per sample (median)").showDefault();
         return [o] { return run(*o); };
     }});

}  // namespace

}  // namespace arcomp
