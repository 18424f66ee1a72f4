#include "runtime/StationRunner.hpp"

#include "runtime/ConfigError.hpp"
#include "runtime/ShutdownSignals.hpp"

#include <spdlog/spdlog.h>

#include <chrono>

namespace arcomp {

namespace {

double nowSeconds() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

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

} // namespace

StationRunner::StationRunner(StationConfig cfg, InputOpener openInput) : cfg_(std::move(cfg)), openInput_(std::move(openInput)) {
    metrics_.setConfig(cfg_.file.string());
    baseVideoFile_ = cfg_.compositing.output.videoFile;
    startStatusServer();
    station_ = std::make_unique<Station>(cfg_, openInput_(cfg_));
    for (const std::string& w : station_->warnings()) {
        spdlog::warn("{}", w);
        metrics_.recordError(w);
    }
}

StationRunner::~StationRunner() { finish(); }

void StationRunner::startStatusServer() {
    server_.reset();
    if (!cfg_.operation.statusEnabled) return;
    try {
        server_ = std::make_unique<StatusServer>(metrics_, cfg_.operation.status);
        spdlog::info("status: http://{}:{}/status and /metrics", cfg_.operation.status.bind, server_->port());
    } catch (const std::exception& e) {
        spdlog::error("{}; running without a status endpoint", e.what());
        metrics_.recordError(e.what());
    }
}

bool StationRunner::step() {
    if (takeReloadRequest()) reload();
    const double start = nowSeconds();
    const std::uint64_t failedBefore = station_->outputFailures();
    const bool drawn = station_->frame();
    if (station_->outputFailures() != failedBefore) reportOutputFailure();
    metrics_.setCamera(station_->inputName(), station_->inputState(), station_->inputDrops());
    if (!drawn) return false;
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
        spdlog::error("{} (output failures so far: {}; the station goes on compositing)", station_->lastOutputError(),
                      outputFailures_);
}

void StationRunner::reload() {
    spdlog::info("reloading {}", cfg_.file.string());
    StationConfig next;
    try {
        next = loadStationConfig(cfg_.file);
    } catch (const ConfigError& e) {
        spdlog::error("reload refused, keeping the running config: {}", e.what());
        metrics_.recordError(std::string("reload refused: ") + e.what());
        return;
    }
    // Replay overrides (output folder, video file) stay as the command set them.
    next.compositing.output.pngDir = cfg_.compositing.output.pngDir;
    if (!baseVideoFile_.empty()) next.compositing.output.videoFile = numberedVideo(baseVideoFile_, reloads_ + 1);
    const bool keepInput = sameVideo(cfg_, next);
    if (keepInput) next.compositing.video = cfg_.compositing.video;  // command-line overrides too
    try {
        const std::uint64_t written = frames_;
        station_->finish();
        StationInput input = keepInput ? station_->releaseInput() : openInput_(next);
        if (!keepInput) station_.reset();  // release the old camera before the new one opens fully
        auto fresh = std::make_unique<Station>(next, std::move(input));
        fresh->setFirstOutputIndex(written);
        station_ = std::move(fresh);
    } catch (const std::exception& e) {
        // The old station has given up its input and outputs: start it again
        // from its own config, recording into the next numbered file.
        spdlog::error("reload failed, restarting the previous config: {}", e.what());
        metrics_.recordError(std::string("reload failed: ") + e.what());
        StationConfig previous = cfg_;
        if (!baseVideoFile_.empty()) previous.compositing.output.videoFile = numberedVideo(baseVideoFile_, reloads_ + 1);
        ++reloads_;
        station_ = std::make_unique<Station>(previous, openInput_(previous));
        station_->setFirstOutputIndex(frames_);
        cfg_ = std::move(previous);
        return;
    }
    const bool statusChanged = next.operation.statusEnabled != cfg_.operation.statusEnabled ||
                               next.operation.status.port != cfg_.operation.status.port ||
                               next.operation.status.bind != cfg_.operation.status.bind;
    cfg_ = std::move(next);
    if (statusChanged) startStatusServer();
    ++reloads_;
    for (const std::string& w : station_->warnings()) {
        spdlog::warn("{}", w);
        metrics_.recordError(w);  // a model that no longer loads shows in /status, as at start
    }
    spdlog::info("reloaded {} ({} objects, input {})", cfg_.file.string(), cfg_.objects.size(), keepInput ? "kept" : "reopened");
}

void StationRunner::finish() {
    if (station_) station_->finish();
}

} // namespace arcomp
