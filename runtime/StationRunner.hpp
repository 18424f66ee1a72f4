#pragma once
// A station's life around its frames: the Station (runtime/Station.hpp, the
// one-frame pipeline), the operator's metrics and status endpoint, and
// reloading the config at a frame boundary when SIGHUP (or a key) asks.
// `arcomp run` (window, live cameras) and `arcomp replay` (headless, files)
// both drive one.
//
//   installShutdownSignals();
//   StationRunner runner(cfg, openInput);         // a GL context must be current
//   while (!stopRequested() && runner.step()) present(runner.station());
//   runner.finish();                              // video files closed, cameras released
//
// A reload that fails (a config error, a missing model) is logged and
// counted, and the station keeps running what it had. A reload keeps the
// input open when the video section is unchanged, and continues the
// output numbering; a video file output goes on in a new numbered file
// (name.1.avi, ...) so the recording made so far stays whole.

#include "runtime/Station.hpp"
#include "runtime/StationMetrics.hpp"
#include "runtime/StatusServer.hpp"

#include <functional>
#include <memory>

namespace arcomp {

class StationRunner {
public:
    using InputOpener = std::function<StationInput(const StationConfig&)>;

    // Throws what Station throws (no first frame, an output that cannot be
    // opened). A status port that cannot be bound is logged, not thrown.
    StationRunner(StationConfig cfg, InputOpener openInput);
    ~StationRunner();

    // One frame, after a pending reload; false when the input has ended.
    bool step();
    void finish();

    Station& station() { return *station_; }
    const StationConfig& config() const { return cfg_; }
    StationMetrics& metrics() { return metrics_; }
    int statusPort() const { return server_ ? server_->port() : -1; }
    std::uint64_t frames() const { return frames_; }
    std::uint64_t reloads() const { return reloads_; }
    // Frames whose file output failed (disk full, ...): each is logged
    // (rate-limited) and counted in /status, and the frames go on.
    std::uint64_t outputFailures() const { return outputFailures_; }

private:
    void reload();
    void startStatusServer();
    void reportOutputFailure();

    StationConfig cfg_;
    InputOpener openInput_;
    StationMetrics metrics_;
    std::unique_ptr<StatusServer> server_;
    std::unique_ptr<Station> station_;
    std::uint64_t frames_ = 0;
    std::uint64_t reloads_ = 0;
    std::uint64_t outputFailures_ = 0;
    std::filesystem::path baseVideoFile_;  // reloads record into name.1.avi, name.2.avi, ...
    double lastStepStart_ = -1.0;  // seconds, steady clock; frame time is start to start
};

} // namespace arcomp
