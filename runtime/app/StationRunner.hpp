#pragma once
// A station's life around its frames: the Station (runtime/station/Station.hpp, the
// one-frame pipeline), the operator's metrics and status endpoint, and
// reloading the config at a frame boundary when SIGHUP (or a key) asks.
// `arcomp run` (window, live cameras) and `arcomp replay` (headless, files)
// both drive one.
//
//   installShutdownSignals();
//   StationRunner runner(file, applyCommandLine, openInput);   // a GL context must be current
//   while (!stopRequested() && runner.step()) present(runner.station());
//   runner.finish();                                            // video files closed
//
// Reload: the new config is loaded, the command line's overrides applied
// again, and everything that can fail without video or GL is checked
// (Station::preflight) while the old station still runs; a config that
// fails is refused, logged and counted, and the old one goes on. An
// unchanged video section keeps the input open; otherwise the old input is
// released before the new one opens. Output numbering continues; a video
// file output goes on in a new numbered file (name.1.avi, ...) so the
// recording made so far stays whole. If the new station still cannot start
// (no first frame), a live station goes back to its previous config (on
// the test pattern if its camera is gone too); a replay ends.
//
// Cues (runtime/triggers/Cue.hpp) are taken before each frame: from the
// OSC listener the runner keeps across reloads (show_control.cues.osc) and
// the station's MQTT cue topic. Each is done or refused, counted in the
// metrics, and a refusal is logged with its sender and why; a reload cue
// reloads as SIGHUP does.

#include "runtime/operator/StationMetrics.hpp"
#include "runtime/operator/StatusServer.hpp"
#include "runtime/showcontrol/OscCueListener.hpp"
#include "runtime/station/Station.hpp"

#include <chrono>
#include <functional>
#include <memory>

namespace arcomp {

class StationRunner {
public:
    using InputOpener = std::function<StationInput(const StationConfig&)>;
    // Applied to every config the runner loads (the first and each reload):
    // the command line's overrides (--video, --out, --gl, ...).
    using ConfigOverride = std::function<void(StationConfig&)>;

    // Throws what Station throws (no first frame, an output that cannot be
    // opened, a bad calibration file). A status port that cannot be bound is
    // logged, not thrown.
    StationRunner(StationConfig cfg, ConfigOverride override, InputOpener openInput);
    ~StationRunner();

    // One frame, after a pending reload; false when the input has ended.
    bool step();
    void finish();

    Station& station() { return *station_; }
    const StationConfig& config() const { return cfg_; }
    StationMetrics& metrics() { return metrics_; }
    int statusPort() const { return server_ ? server_->port() : -1; }
    // The OSC cue port bound; -1 without one.
    int cuePort() const { return cueListener_ ? cueListener_->port() : -1; }
    CueInputCounts cueCounts() const { return cueListener_ ? cueListener_->counts() : CueInputCounts{}; }
    StatusServerCounters statusCounters() const { return server_ ? server_->counters() : StatusServerCounters{}; }
    std::uint64_t frames() const { return frames_; }
    std::uint64_t reloads() const { return reloads_; }
    // Frames whose file output failed (disk full, ...): each is logged
    // (rate-limited) and counted in /status, and the frames go on.
    std::uint64_t outputFailures() const { return outputFailures_; }

private:
    void reload();
    void restart(StationConfig cfg, StationInput input);
    void startStatusServer();
    void startCueListener();
    // Does the cues that have come; true when one asks for a reload.
    bool takeCues();
    void reportWarnings();
    void reportOutputFailure();

    StationConfig cfg_;
    ConfigOverride override_;
    InputOpener openInput_;
    StationMetrics metrics_;
    std::unique_ptr<StatusServer> server_;
    std::unique_ptr<OscCueListener> cueListener_;
    std::vector<ReceivedCue> received_;
    std::uint64_t cuesRefused_ = 0;
    std::unique_ptr<Station> station_;
    std::uint64_t frames_ = 0;
    std::uint64_t reloads_ = 0;
    const std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();  // live movers' clock
    bool ended_ = false;  // a replay whose reload could not start
    std::uint64_t outputFailures_ = 0;
    double lastStepStart_ = -1.0;  // seconds, steady clock; frame time is start to start
};

}  // namespace arcomp
