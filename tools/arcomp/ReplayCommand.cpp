// arcomp replay <station.yaml> --out DIR [--frames N] [--video FILE]:
// the station's whole frame, headless, fed frame by frame from a file;
// composited frames go to DIR as frame-000000.png, ... Deterministic: the
// same input gives bit-identical images on the same machine.

#include "runtime/GlContext.hpp"
#include "runtime/ReplayInput.hpp"
#include "runtime/Station.hpp"
#include "tools/arcomp/Command.hpp"
#include "video/VideoError.hpp"

#include <iostream>
#include <memory>

namespace arcomp {
namespace {

struct ReplayOptions {
    std::string config, out, video, videoOut;
    long frames = -1;
};

// Without --frames a file plays to its end; an endless pattern stops here.
constexpr long kPatternFrames = 120;

int replay(const ReplayOptions& o) {
    StationConfig cfg = loadStationConfig(o.config);
    if (!o.video.empty()) {
        SourceSpec spec = cfg.compositing.video.value_or(SourceSpec{});
        spec.kind = SourceKind::File;
        spec.path = o.video;  // relative to where the user stands, like any command-line path
        spec.fallback = {};
        cfg.compositing.video = spec;
    }
    if (!cfg.compositing.video)
        throw InputError(o.config + ": no `video` section and no --video FILE: nothing to replay");
    cfg.compositing.output.pngDir = o.out;
    if (!o.videoOut.empty()) cfg.compositing.output.videoFile = o.videoOut;

    std::vector<std::string> warnings;
    StationInput input;
    try {
        input = openReplayInput(*cfg.compositing.video, warnings);
    } catch (const VideoError& e) {
        throw InputError(e.what());
    }
    const bool endless = cfg.compositing.video->kind == SourceKind::Pattern || !warnings.empty() ||
                         cfg.compositing.video->loop;
    const long frames = o.frames >= 0 ? o.frames : endless ? kPatternFrames : -1;
    for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";

    bool isAuto = false;
    const auto api = parseGlApi(cfg.render.gl, isAuto);
    auto context = HeadlessContext::create(isAuto ? GlRequest::Auto : *api == GlApiKind::Es3 ? GlRequest::Es3 : GlRequest::Gl33);
    Station station(cfg, std::move(input));
    for (const std::string& w : station.warnings()) std::cerr << "warning: " << w << "\n";

    double total = 0.0;
    long done = 0;
    while ((frames < 0 || done < frames) && station.frame()) {
        ++done;
        total += station.stats().totalMs;
        if (done % 25 == 0) std::cerr << "frame " << done << "\n";
    }
    station.finish();
    if (!station.inputEnd().empty() && frames < 0) std::cerr << "input: " << station.inputEnd() << "\n";
    std::cout << "replayed " << done << " frames (" << station.size().x << "x" << station.size().y << ", "
              << toString(context->api()) << ", " << (done ? total / static_cast<double>(done) : 0.0)
              << " ms/frame) into " << o.out << "/frame-NNNNNN.png";
    if (!cfg.compositing.output.videoFile.empty()) std::cout << " and " << cfg.compositing.output.videoFile.string();
    std::cout << "\n";
    return done > 0 ? kExitOk : kExitFailure;
}

const bool registered = registerCommand(
    {"replay", "Composite a station's video file headless, frame by frame, into PNG frames (deterministic)",
     [](CLI::App& app) {
         auto o = std::make_shared<ReplayOptions>();
         app.add_option("config", o->config, "Station config (.yaml)")->required();
         app.add_option("--out", o->out, "Folder for frame-NNNNNN.png")->required();
         app.add_option("--frames", o->frames, "Stop after N frames (default: the whole file)");
         app.add_option("--video", o->video, "Replay this file instead of the config's video source");
         app.add_option("--video-out", o->videoOut, "Also write the composited frames to this video file");
         return [o] { return replay(*o); };
     }});

} // namespace
} // namespace arcomp
