#pragma once
// What an operator can learn about a running station: frame times, drops,
// camera states, the people and where they are sent, and the last errors.
// The frame loop records into it; the status server renders it as JSON
// (/status) and Prometheus text (/metrics) from another thread, so every
// call takes a short lock.
//
//   StationMetrics metrics;
//   metrics.recordFrame(16.4);                              // each frame, ms
//   metrics.setCamera("front", {SourceStatus::Streaming, ""}, drops);
//   metrics.setPeople(station.people().people.size(), station.showControl().outputs());
//   metrics.setZones(station.people().zones, triggers);     // /status zones, arcomp_zone_people{zone}
//   metrics.setStreams(station.streamStatus());              // /status streams, arcomp_stream_*{stream}
//   std::string text = metrics.prometheusText();

#include "runtime/people/PeopleFrame.hpp"
#include "runtime/showcontrol/ShowControl.hpp"
#include "video/sources/SourceStatus.hpp"
#include "video/streams/StreamOutputs.hpp"

#include <array>
#include <chrono>
#include <cstdint>
#include <deque>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace arcomp {

// A trigger as the operator sees it.
struct TriggerStatus {
    std::string name;
    std::uint64_t fired = 0;
    bool holds = false;
};

class StationMetrics {
public:
    // Upper bounds of the frame-time histogram, in seconds (Prometheus `le`).
    static constexpr std::array<double, 9> kFrameTimeBuckets{0.005, 0.010, 0.0167, 0.020, 0.0333,
                                                             0.050, 0.100, 0.250,  1.0};

    StationMetrics();

    void recordFrame(double frameMs);
    // `drops` is the source's running total; `reconnects` counts transitions
    // from lost back to streaming, which the station sees and the source does not report.
    void setCamera(const std::string& name, const SourceState& state, std::uint64_t drops);
    // This frame's people, and each show-control output's state and counts.
    void setPeople(std::size_t people, std::vector<OutputStatus> outputs);
    // This frame's zones with their occupancy, and the triggers.
    void setZones(const std::vector<ZoneCount>& zones, std::vector<TriggerStatus> triggers);
    // Each output stream's state, bitrate, drops and reconnects.
    void setStreams(std::vector<StreamStatus> streams);
    // A cue from show control, done or refused (a sender not allowed, a malformed packet, an unknown object).
    void recordCue(bool accepted);
    void recordError(std::string message);
    // A reload replaced the inputs: cameras no longer in use leave the report.
    void forgetCameras();
    void setConfig(std::string file);

    std::string statusJson() const;
    std::string prometheusText() const;

private:
    struct Camera {
        SourceState state;
        std::uint64_t drops = 0;
        std::uint64_t reconnects = 0;
        bool wasLost = false;
    };
    mutable std::mutex mutex_;
    std::chrono::steady_clock::time_point started_;
    std::string config_;
    std::uint64_t frames_ = 0;
    double frameSecondsSum_ = 0.0;
    std::array<std::uint64_t, kFrameTimeBuckets.size()> bucketCounts_{};  // not cumulative
    std::deque<std::chrono::steady_clock::time_point>
        recentFrames_;  // for fps: the last second's, pruned as it is read
    std::size_t framesInLastSecond() const;
    double lastFrameMs_ = 0.0;
    std::map<std::string, Camera> cameras_;
    std::size_t people_ = 0;
    std::vector<OutputStatus> outputs_;
    std::vector<ZoneCount> zones_;
    std::vector<TriggerStatus> triggers_;
    std::vector<StreamStatus> streams_;
    std::uint64_t cuesAccepted_ = 0, cuesRefused_ = 0;
    std::deque<std::string> lastErrors_;  // newest last, the last ten
    std::uint64_t errors_ = 0;
};

}  // namespace arcomp
