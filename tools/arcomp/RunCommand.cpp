// arcomp run <station.yaml>: the live station. A full-screen window (or
// --windowed), the config's camera composited with its scene, frame after
// frame until SIGTERM, the quit key or --frames. A camera that fails shows
// its fallback; a station whose camera never delivers runs on the test
// pattern rather than leaving the kiosk dark.
//
// Keys: Tab toggles the stats overlay (with a calibrated camera it also
// draws the floor grid and each person's foot point, id and distance over
// the video), F12 or P saves a screenshot, R reloads the config (as SIGHUP
// does), Esc or Q quits.

#include "graph/core/JoinText.hpp"
#include "runtime/app/CalibrationOverlay.hpp"
#include "runtime/app/ShutdownSignals.hpp"
#include "runtime/app/StationRunner.hpp"
#include "runtime/app/StatsOverlay.hpp"
#include "runtime/app/WindowPresenter.hpp"
#include "runtime/app/ZoneOverlay.hpp"
#include "runtime/gl/WindowContext.hpp"
#include "runtime/operator/StationLog.hpp"
#include "runtime/station/ImageFile.hpp"
#include "tools/cli/CliParse.hpp"
#include "tools/cli/Command.hpp"
#include "video/pixels/VideoError.hpp"
#include "video/sources/OpenSource.hpp"

#include <GLFW/glfw3.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <iostream>
#include <memory>

namespace arcomp {
namespace {

struct RunOptions {
    std::string config, size = "1280x720", screenshot, logLevel;
    long frames = -1;
    bool windowed = false, overlay = false;
    int monitor = 0;
};

StationInput openLive(const StationConfig& cfg) {
    SourceSpec spec = cfg.compositing.video.value_or(SourceSpec{});  // no video section: the test pattern
    auto source = openSource(spec);
    return StationInput::fromLive(std::move(source), spec.fps);
}

// A kiosk never goes dark over its input or its settings: whatever stops the
// config's station from starting (a camera that never delivers, a bad
// calibration or gaze file), it runs the same scene on the test pattern
// with every optional part off, and says why on /status.
std::unique_ptr<StationRunner> startStation(const StationConfig& cfg) {
    try {
        return std::make_unique<StationRunner>(cfg, nullptr, openLive);
    } catch (const std::exception& e) {
        spdlog::error(joinText(e.what(), "; showing the test pattern instead"));
        StationConfig plain = cfg;
        plain.compositing.video = SourceSpec{};
        plain.compositing.matte = {};
        plain.budget.enabled = false;
        plain.gaze = {};
        auto runner = std::make_unique<StationRunner>(plain, nullptr, openLive);
        runner->metrics().recordError(e.what());
        return runner;
    }
}

int run(const RunOptions& o) {
    const StationConfig cfg = loadStationConfig(o.config);
    configureLogging({.level = o.logLevel.empty() ? cfg.operation.log.level : o.logLevel,
                      .file = cfg.operation.log.file,
                      .maxMegabytes = cfg.operation.log.maxMegabytes,
                      .files = cfg.operation.log.files});
    bool isAuto = false;
    const auto api = parseGlApi(cfg.render.gl, isAuto);
    auto window = WindowContext::create({.title = "arcomp: " + o.config,
                                         .size = parseSize(o.size, "--size"),
                                         .fullscreen = !o.windowed,
                                         .monitor = o.monitor,
                                         .vsync = true,
                                         .hideCursor = true},
                                        isAuto                   ? GlRequest::Auto
                                        : *api == GlApiKind::Es3 ? GlRequest::Es3
                                                                 : GlRequest::Gl33);
    installShutdownSignals();
    std::unique_ptr<StationRunner> runner = startStation(cfg);
    WindowPresenter presenter;
    StatsOverlay overlay;
    CalibrationOverlay calibration;
    ZoneOverlay zoneOverlay;

    bool showOverlay = o.overlay, takeScreenshot = false;
    window->onKey([&](int key) {
        if (key == GLFW_KEY_TAB)
            showOverlay = !showOverlay;
        else if (key == GLFW_KEY_F12 || key == GLFW_KEY_P)
            takeScreenshot = true;
        else if (key == GLFW_KEY_R)
            requestReload();
        else if (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_Q)
            window->requestClose();
    });

    long done = 0;
    auto last = std::chrono::steady_clock::now();
    while (!stopRequested() && !window->shouldClose() && (o.frames < 0 || done < o.frames)) {
        if (!runner->step()) {
            // Only a file source that ended stops a live station (a camera
            // that is lost shows its fallback and keeps the loop going).
            if (runner->station().inputState().status == SourceStatus::Ended) break;
            window->poll();
            continue;
        }
        ++done;
        const auto now = std::chrono::steady_clock::now();
        const double frameMs = std::chrono::duration<double, std::milli>(now - last).count();
        last = now;
        const Station& station = runner->station();
        const FrameStats& stats = station.stats();
        overlay.add(stats, station.drawList(), {station.inputName(), station.inputState(), station.inputDrops()},
                    frameMs, stats.budget ? runner->config().budget.targetMs : 1000.0 / 60.0);
        // The config of the station running now: a reload may bring another camera file.
        const std::optional<CalibratedCamera>& camera = runner->config().camera.calibrated;
        const cv::Mat* frameOverlay = nullptr;
        if (showOverlay && camera) {
            calibration.draw(*camera, station.size(), station.standingPeople());
            frameOverlay = &calibration.image();
        }
        if (showOverlay && !runner->config().zones.empty()) {
            zoneOverlay.draw(frameOverlay, runner->config().zones, station.people().zones, camera, station.size());
            frameOverlay = &zoneOverlay.image();
        }
        const glm::ivec2 size = window->framebufferSize();
        presenter.present(station.compositedFrame(), size, showOverlay ? &overlay.image() : nullptr, frameOverlay);
        const bool finalFrame = o.frames >= 0 && done == o.frames;
        if (takeScreenshot || (finalFrame && !o.screenshot.empty())) {
            const std::string file =
                finalFrame && !o.screenshot.empty() ? o.screenshot : "screenshot-" + std::to_string(done) + ".png";
            try {
                writePng(file, presenter.screenshot(size));
                spdlog::info(joinText("screenshot ", file));
            } catch (const std::exception& e) {
                spdlog::error(joinText("screenshot not saved: ", e.what()));
                runner->metrics().recordError(e.what());
            }
            takeScreenshot = false;
        }
        window->swap();
        window->poll();
    }
    runner->finish();
    spdlog::info(joinText("station stopped after ", done, " frames"));
    return kExitOk;
}

const bool registered = registerCommand(
    {"run", "Run a station live: cameras, scene and compositing in a (full-screen) window", [](CommandLine& line) {
         auto o = std::make_shared<RunOptions>();
         line.option("config", o->config, "Station config (.yaml)").required();
         line.option("--frames", o->frames, "Quit after N frames (default: run until stopped)");
         line.flag("--windowed", o->windowed, "A window instead of full screen");
         line.option("--monitor", o->monitor, "Monitor index for full screen").showDefault();
         line.option("--size", o->size, "Window size WIDTHxHEIGHT when windowed").showDefault();
         line.flag(
             "--overlay", o->overlay,
             "Show the stats overlay, and the floor grid with a calibrated camera, from the start (Tab toggles it)");
         line.option("--screenshot", o->screenshot, "With --frames: save the last frame shown to this PNG");
         line.option("--log-level", o->logLevel,
                     "trace, debug, info, warn, error, critical or off (default: the config's)")
             .oneOf({"trace", "debug", "info", "warn", "error", "critical", "off"});
         return [o] { return run(*o); };
     }});

}  // namespace
}  // namespace arcomp
