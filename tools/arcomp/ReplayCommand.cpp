// arcomp replay <station.yaml> --out DIR [--frames N] [--video FILE]:
// the station's whole frame, headless, fed frame by frame from a file;
// composited frames go to DIR as frame-000000.png, ... Deterministic: the
// same input gives bit-identical images on the same machine.

#include "runtime/app/ShutdownSignals.hpp"
#include "runtime/app/StationRunner.hpp"
#include "runtime/gl/GlContext.hpp"
#include "runtime/operator/StationLog.hpp"
#include "runtime/station/ReplayInput.hpp"
#include "tools/cli/Command.hpp"

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

namespace arcomp {
namespace {

struct ReplayOptions {
    std::string config, out, video, videoOut, logLevel, gl;
    long frames = -1;
};

// Without --frames a file plays to its end; an endless pattern stops here.
constexpr long kPatternFrames = 120;

// The command line wins over the config, on start and on every reload.
void applyCommandLine(const ReplayOptions& o, StationConfig& cfg) {
    if (!o.video.empty()) {
        SourceSpec spec = cfg.compositing.video.value_or(SourceSpec{});
        spec.kind = SourceKind::File;
        spec.path = o.video;  // relative to where the user stands, like any command-line path
        spec.fallback = {};
        cfg.compositing.video = spec;
    }
    if (!cfg.compositing.video)
        throw InputError(cfg.file.string() + ": no `video` section and no --video FILE: nothing to replay");
    cfg.compositing.output.pngDir = o.out;
    // The event log and the triggers' snapshots and clips go beside the
    // frames, as the review of one replay.
    if (!cfg.compositing.output.events.empty())
        cfg.compositing.output.events = std::filesystem::path(o.out) / cfg.compositing.output.events.filename();
    for (Trigger& t : cfg.triggers)
        for (auto* actions : {&t.actions, &t.onEnd})
            for (TriggerAction& a : *actions)
                if (!a.folder.empty()) a.folder = std::filesystem::path(o.out) / a.folder.filename();
    if (!o.videoOut.empty()) cfg.compositing.output.videoFile = o.videoOut;
    if (!o.gl.empty()) cfg.render.gl = o.gl;
}

int replay(const ReplayOptions& o) {
    StationConfig cfg = loadStationConfig(o.config);
    applyCommandLine(o, cfg);

    configureLogging({.level = o.logLevel.empty() ? cfg.operation.log.level : o.logLevel,
                      .file = cfg.operation.log.file,
                      .maxMegabytes = cfg.operation.log.maxMegabytes,
                      .files = cfg.operation.log.files});

    // The replay input opens before the context so that a missing file is
    // bad input (exit 2) rather than a runtime failure. A reload with a
    // changed video section opens again through the same path.
    std::vector<std::string> warnings;
    std::optional<StationInput> first = openReplayInput(*cfg.compositing.video, warnings);
    const bool endless =
        cfg.compositing.video->kind == SourceKind::Pattern || !warnings.empty() || cfg.compositing.video->loop;
    const long frames = o.frames >= 0 ? o.frames : endless ? kPatternFrames : -1;
    for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";
    auto openInput = [&first](const StationConfig& c) {
        if (first) {
            StationInput in = std::move(*first);
            first.reset();
            return in;
        }
        std::vector<std::string> ignored;
        return openReplayInput(*c.compositing.video, ignored);
    };

    bool isAuto = false;
    const auto api = parseGlApi(cfg.render.gl, isAuto);
    auto context = HeadlessContext::create(isAuto                   ? GlRequest::Auto
                                           : *api == GlApiKind::Es3 ? GlRequest::Es3
                                                                    : GlRequest::Gl33);
    installShutdownSignals();
    StationRunner runner(
        cfg, [&o](StationConfig& c) { applyCommandLine(o, c); }, openInput);

    double total = 0.0;
    long done = 0;
    while ((frames < 0 || done < frames) && !stopRequested() && runner.step()) {
        ++done;
        total += runner.station().stats().totalMs;
        if (done % 25 == 0) std::cerr << "frame " << done << "\n";
    }
    runner.finish();
    if (stopRequested()) std::cerr << "stopped by signal after " << done << " frames; outputs finished\n";
    const Station& station = runner.station();
    if (!station.inputEnd().empty() && frames < 0) std::cerr << "input: " << station.inputEnd() << "\n";
    std::cout << "replayed " << done << " frames (" << station.size().x << "x" << station.size().y << ", "
              << toString(context->api()) << ", " << (done ? total / static_cast<double>(done) : 0.0)
              << " ms/frame) into " << o.out << "/frame-NNNNNN.png";
    if (!runner.config().compositing.output.videoFile.empty())
        std::cout << " and " << runner.config().compositing.output.videoFile.string();
    std::cout << "\n";
    // A stream drops what its receiver cannot take, in replay too: said, not failed.
    for (const StreamStatus& s : station.streamStatus())
        std::cout << "stream " << s.name << " (" << s.target << "): " << s.framesIn << " frames, " << s.dropped
                  << " dropped, " << s.reconnects << " reconnects, " << s.bytes / 1024 << " KiB encoded"
                  << (s.lastError.empty() ? "" : "; last error: " + s.lastError) << "\n";
    if (runner.outputFailures() > 0) {
        // Every frame was composited; some files are missing. The ones written are whole.
        std::cerr << "error: " << runner.outputFailures() << " of " << done
                  << " frames could not be written; last: " << station.lastOutputError() << "\n";
        return kExitFailure;
    }
    return done > 0 ? kExitOk : kExitFailure;
}

const bool registered = registerCommand(
    {"replay", "Composite a station's video file headless, frame by frame, into PNG frames (deterministic)",
     [](CommandLine& line) {
         auto o = std::make_shared<ReplayOptions>();
         line.option("config", o->config, "Station config (.yaml)").required();
         line.option("--out", o->out, "Folder for frame-NNNNNN.png").required();
         line.option("--frames", o->frames, "Stop after N frames (default: the whole file)");
         line.option("--video", o->video, "Replay this file instead of the config's video source");
         line.option("--video-out", o->videoOut, "Also write the composited frames to this video file");
         line.option("--gl", o->gl, "OpenGL API: auto, gl33 or es3 (default: the config's render.gl)")
             .oneOf({"auto", "gl33", "es3"});
         line.option("--log-level", o->logLevel,
                     "trace, debug, info, warn, error, critical or off (default: the config's)")
             .oneOf({"trace", "debug", "info", "warn", "error", "critical", "off"});
         return [o] { return replay(*o); };
     }});

}  // namespace
}  // namespace arcomp
