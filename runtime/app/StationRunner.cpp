#include "runtime/app/StationRunner.hpp"
#include "graph/core/JoinText.hpp"

#include "runtime/app/ShutdownSignals.hpp"
#include "runtime/config/ConfigError.hpp"
#include "runtime/showcontrol/CueDecode.hpp"

#include <spdlog/spdlog.h>

#include <chrono>

namespace arcomp {

namespace {

double nowSeconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

bool sameVideo(const StationConfig& a, const StationConfig& b) {
    const auto& x = a.compositing.video;
    const auto& y = b.compositing.video;
    if (!x || !y) return !x && !y;
    return x->kind == y->kind && x->path == y->path && x->width == y->width && x->height == y->height &&
           x->fps == y->fps && x->loop == y->loop && x->formats == y->formats;
}

// name.avi -> name.1.avi: a reloaded station must not overwrite the recording.
std::filesystem::path numberedVideo(const std::filesystem::path& file, std::uint64_t reload) {
    std::filesystem::path out = file;
    out.replace_filename(file.stem().string() + "." + std::to_string(reload) + file.extension().string());
    return out;
}

}  // namespace

StationRunner::StationRunner(StationConfig cfg, ConfigOverride override, InputOpener openInput)
    : cfg_(std::move(cfg)), override_(std::move(override)), openInput_(std::move(openInput)) {
    if (override_) override_(cfg_);
    metrics_.setConfig(cfg_.file.string());
    startStatusServer();
    startCueListener();
    station_ = std::make_unique<Station>(cfg_, openInput_(cfg_));
    station_->setClockStart(started_);
    reportWarnings();
}

StationRunner::~StationRunner() { finish(); }

void StationRunner::startStatusServer() {
    server_.reset();
    if (!cfg_.operation.statusEnabled) return;
    try {
        server_ = std::make_unique<StatusServer>(metrics_, cfg_.operation.status);
        spdlog::info(
            joinText("status: http://", cfg_.operation.status.bind, ":", server_->port(), "/status and /metrics"));
    } catch (const std::exception& e) {
        spdlog::error(joinText(e.what(), "; running without a status endpoint"));
        metrics_.recordError(e.what());
    }
}

void StationRunner::reportWarnings() {
    for (const std::string& w : station_->warnings()) {
        spdlog::warn(w);
        metrics_.recordError(w);
    }
}

void StationRunner::startCueListener() {
    cueListener_.reset();
    if (!cfg_.showControl.cues.osc) return;
    try {
        cueListener_ = std::make_unique<OscCueListener>(cfg_.showControl.cues);
        spdlog::info(joinText("cues: OSC ", kOscCuePrefix, "<verb> on ", cfg_.showControl.cues.listen.host, ":",
                              cueListener_->port()));
    } catch (const std::exception& e) {
        spdlog::error(joinText(e.what(), "; running without OSC cues"));
        metrics_.recordError(e.what());
    }
}

bool StationRunner::takeCues() {
    received_.clear();
    if (cueListener_) cueListener_->poll(received_);
    for (const std::string& payload : station_->takeMqttCues()) {
        CueDecoded d = decodeJsonCue(payload);
        received_.push_back({.sender = "mqtt", .cue = std::move(d.cue), .error = std::move(d.error)});
    }
    bool reload = false;
    for (const ReceivedCue& r : received_) {
        std::string why = r.error;
        if (r.cue && r.cue->kind == Cue::Kind::Reload)
            reload = true;
        else if (r.cue)
            why = station_->cue(*r.cue);
        metrics_.recordCue(why.empty());
        if (why.empty()) continue;
        ++cuesRefused_;
        // The first refusals, then one line per 100, so a flood of bad packets does not also fill the log.
        if (cuesRefused_ <= 10 || cuesRefused_ % 100 == 0)
            spdlog::warn(joinText("cue from ", r.sender, " refused: ", why, " (refused so far: ", cuesRefused_, ")"));
    }
    return reload;
}

bool StationRunner::step() {
    if (takeCues() | takeReloadRequest()) reload();
    if (ended_) return false;
    const double start = nowSeconds();
    const std::uint64_t failedBefore = station_->outputFailures();
    const bool drawn = station_->frame();
    if (station_->outputFailures() != failedBefore) reportOutputFailure();
    metrics_.setCamera(station_->inputName(), station_->inputState(), station_->inputDrops());
    if (!drawn) return false;
    metrics_.setPeople(station_->people().people.size(), station_->showControl().outputs());
    std::vector<TriggerStatus> triggers;
    const Triggers& t = station_->triggers();
    for (std::size_t i = 0; i < t.triggers().size(); ++i)
        triggers.push_back({t.triggers()[i].name, t.counts(i).fired, t.holds(i)});
    metrics_.setZones(station_->people().zones, std::move(triggers));
    metrics_.setStreams(station_->streamStatus());
    ++frames_;
    // Start to start, so a window's vsync wait and presentation count.
    metrics_.recordFrame(lastStepStart_ < 0.0 ? station_->stats().totalMs : (start - lastStepStart_) * 1000.0);
    lastStepStart_ = start;
    return true;
}

void StationRunner::reportOutputFailure() {
    ++outputFailures_;
    metrics_.recordError("output: " + station_->lastOutputError());
    // The first failure, then one line per 100, so a full disk does not also fill the log.
    if (outputFailures_ == 1 || outputFailures_ % 100 == 0)
        spdlog::error(joinText(station_->lastOutputError(), " (output failures so far: ", outputFailures_,
                               "; the station goes on compositing)"));
}

void StationRunner::reload() {
    spdlog::info("reloading " + cfg_.file.string());
    StationConfig next;
    try {
        next = loadStationConfig(cfg_.file);
        if (override_) override_(next);
        Station::preflight(next);
    } catch (const std::exception& e) {
        spdlog::error(joinText("reload refused, keeping the running config: ", e.what()));
        metrics_.recordError(std::string("reload refused: ") + e.what());
        return;
    }
    ++reloads_;
    if (!next.compositing.output.videoFile.empty())
        next.compositing.output.videoFile = numberedVideo(next.compositing.output.videoFile, reloads_);
    const bool keepInput = sameVideo(cfg_, next);
    StationInput input;
    if (keepInput) {
        input = station_->releaseInput();
    } else {
        station_.reset();  // the old camera is released before the new one opens
        metrics_.forgetCameras();
    }
    try {
        restart(next, keepInput ? std::move(input) : openInput_(next));
    } catch (const std::exception& e) {
        spdlog::error(joinText("reload failed: ", e.what()));
        metrics_.recordError(std::string("reload failed: ") + e.what());
        if (cfg_.compositing.video && cfg_.compositing.video->kind == SourceKind::File &&
            !cfg_.compositing.video->loop) {
            // A replay cannot go back to where it was without repeating frames.
            ended_ = true;
            return;
        }
        StationConfig previous = cfg_;
        if (!previous.compositing.output.videoFile.empty())
            previous.compositing.output.videoFile = numberedVideo(previous.compositing.output.videoFile, reloads_);
        station_.reset();
        try {
            restart(previous, openInput_(previous));
        } catch (const std::exception& again) {
            spdlog::error(
                joinText("the previous config cannot start either (", again.what(), "); showing the test pattern"));
            previous.compositing.video = SourceSpec{};
            restart(previous, openInput_(previous));
        }
        return;
    }
    spdlog::info(joinText("reloaded ", cfg_.file.string(), " (", cfg_.objects.size(), " objects, input ",
                          keepInput ? "kept" : "reopened", ")"));
}

void StationRunner::restart(StationConfig cfg, StationInput input) {
    auto fresh = std::make_unique<Station>(cfg, std::move(input));
    fresh->setFirstOutputIndex(frames_);
    fresh->setClockStart(started_);
    station_ = std::move(fresh);
    // A reload reads the token file again, so a rotated token takes effect.
    const bool statusChanged = cfg.operation.statusEnabled != cfg_.operation.statusEnabled ||
                               cfg.operation.status != cfg_.operation.status || !cfg.operation.status.tokenFile.empty();
    const bool cuesChanged = cfg.showControl.cues.osc != cfg_.showControl.cues.osc ||
                             cfg.showControl.cues.listen.text() != cfg_.showControl.cues.listen.text() ||
                             cfg.showControl.cues.allow != cfg_.showControl.cues.allow;
    cfg_ = std::move(cfg);
    if (statusChanged) startStatusServer();
    if (cuesChanged) startCueListener();
    reportWarnings();
}

void StationRunner::finish() {
    if (station_) station_->finish();
}

}  // namespace arcomp
