#include "runtime/operator/StationMetrics.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <sstream>

namespace arcomp {

namespace {

constexpr std::size_t kKeptErrors = 10;

// Prometheus label values escape backslash, quote and newline.
std::string labelValue(std::string_view text) {
    std::string out;
    for (char c : text) {
        if (c == '\\' || c == '"') out += '\\';
        if (c == '\n')
            out += "\\n";
        else
            out += c;
    }
    return out;
}

}  // namespace

StationMetrics::StationMetrics() : started_(std::chrono::steady_clock::now()) {}

void StationMetrics::recordFrame(double frameMs) {
    const auto now = std::chrono::steady_clock::now();
    std::lock_guard lock(mutex_);
    ++frames_;
    lastFrameMs_ = frameMs;
    frameSecondsSum_ += frameMs / 1000.0;
    for (std::size_t i = 0; i < kFrameTimeBuckets.size(); ++i)
        if (frameMs / 1000.0 <= kFrameTimeBuckets[i]) {
            ++bucketCounts_[i];
            break;
        }
    recentFrames_.push_back(now);
    while (now - recentFrames_.front() > std::chrono::seconds(1)) recentFrames_.pop_front();
}

// A stalled loop records nothing, so the count is taken against the time of
// reading, not of the last frame.
std::size_t StationMetrics::framesInLastSecond() const {
    const auto since = std::chrono::steady_clock::now() - std::chrono::seconds(1);
    return static_cast<std::size_t>(
        std::count_if(recentFrames_.begin(), recentFrames_.end(), [&](auto t) { return t > since; }));
}

void StationMetrics::forgetCameras() {
    std::lock_guard lock(mutex_);
    cameras_.clear();
}

void StationMetrics::setCamera(const std::string& name, const SourceState& state, std::uint64_t drops) {
    std::lock_guard lock(mutex_);
    Camera& camera = cameras_[name];
    const bool lost = isLost(state.status) || state.status == SourceStatus::Stalled;
    if (camera.wasLost && state.status == SourceStatus::Streaming) ++camera.reconnects;
    if (lost)
        camera.wasLost = true;
    else if (state.status == SourceStatus::Streaming)
        camera.wasLost = false;
    camera.state = state;
    camera.drops = drops;
}

void StationMetrics::setZones(const std::vector<ZoneCount>& zones, std::vector<TriggerStatus> triggers) {
    std::lock_guard lock(mutex_);
    zones_ = zones;
    triggers_ = std::move(triggers);
}

void StationMetrics::setStreams(std::vector<StreamStatus> streams) {
    std::lock_guard lock(mutex_);
    streams_ = std::move(streams);
}

void StationMetrics::recordCue(bool accepted) {
    std::lock_guard lock(mutex_);
    ++(accepted ? cuesAccepted_ : cuesRefused_);
}

void StationMetrics::setPeople(std::size_t people, std::vector<OutputStatus> outputs) {
    std::lock_guard lock(mutex_);
    people_ = people;
    outputs_ = std::move(outputs);
}

void StationMetrics::recordError(std::string message) {
    std::lock_guard lock(mutex_);
    ++errors_;
    lastErrors_.push_back(std::move(message));
    if (lastErrors_.size() > kKeptErrors) lastErrors_.pop_front();
}

void StationMetrics::setConfig(std::string file) {
    std::lock_guard lock(mutex_);
    config_ = std::move(file);
}

std::string StationMetrics::statusJson() const {
    std::lock_guard lock(mutex_);
    const double uptime = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    nlohmann::ordered_json status = {{"config", config_},
                                     {"uptime_s", uptime},
                                     {"frames", frames_},
                                     {"fps", framesInLastSecond()},
                                     {"last_frame_ms", lastFrameMs_}};
    nlohmann::ordered_json& cameras = status["cameras"] = nlohmann::ordered_json::array();
    for (const auto& [name, camera] : cameras_)
        cameras.push_back({{"name", name},
                           {"state", sourceStatusName(camera.state.status)},
                           {"reason", camera.state.reason},
                           {"drops", camera.drops},
                           {"reconnects", camera.reconnects}});
    status["people"] = people_;
    nlohmann::ordered_json& outputs = status["outputs"] = nlohmann::ordered_json::array();
    for (const OutputStatus& o : outputs_)
        outputs.push_back({{"kind", o.kind},
                           {"target", o.target},
                           {"state", o.state},
                           {"sent", o.sent},
                           {"dropped", o.dropped},
                           {"queued", o.queued},
                           {"last_error", o.lastError}});
    nlohmann::ordered_json& zones = status["zones"] = nlohmann::ordered_json::array();
    for (const ZoneCount& z : zones_) zones.push_back({{"name", z.name}, {"people", z.people}, {"entries", z.entries}});
    nlohmann::ordered_json& triggers = status["triggers"] = nlohmann::ordered_json::array();
    for (const TriggerStatus& t : triggers_)
        triggers.push_back({{"name", t.name}, {"fired", t.fired}, {"holds", t.holds}});
    status["cues"] = {{"accepted", cuesAccepted_}, {"refused", cuesRefused_}};
    nlohmann::ordered_json& streams = status["streams"] = nlohmann::ordered_json::array();
    for (const StreamStatus& st : streams_)
        streams.push_back({{"name", st.name},
                           {"target", st.target},
                           {"state", st.state == StreamState::Streaming ? "streaming" : "retrying"},
                           {"frames", st.framesIn},
                           {"dropped", st.dropped},
                           {"packets_dropped", st.packetsDropped},
                           {"reconnects", st.reconnects},
                           {"clients", st.clients},
                           {"kbps", st.kbps},
                           {"last_error", st.lastError},
                           {"warning", st.warning}});
    status["errors"] = errors_;
    status["last_errors"] = lastErrors_;
    // A device name or an OS message that is not UTF-8 must not cost the
    // operator the whole document: such bytes become U+FFFD.
    return status.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string StationMetrics::prometheusText() const {
    std::lock_guard lock(mutex_);
    const double uptime = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    std::ostringstream s;
    s << "# HELP arcomp_uptime_seconds Seconds since the station started.\n"
         "# TYPE arcomp_uptime_seconds gauge\n"
      << "arcomp_uptime_seconds " << uptime << '\n'
      << "# HELP arcomp_frame_time_seconds Time from one frame's start to the next.\n"
         "# TYPE arcomp_frame_time_seconds histogram\n";
    std::uint64_t cumulative = 0;
    for (std::size_t i = 0; i < kFrameTimeBuckets.size(); ++i) {
        cumulative += bucketCounts_[i];
        s << "arcomp_frame_time_seconds_bucket{le=\"" << kFrameTimeBuckets[i] << "\"} " << cumulative << '\n';
    }
    s << "arcomp_frame_time_seconds_bucket{le=\"+Inf\"} " << frames_ << '\n'
      << "arcomp_frame_time_seconds_sum " << frameSecondsSum_ << '\n'
      << "arcomp_frame_time_seconds_count " << frames_ << '\n'
      << "# HELP arcomp_frames_per_second Frames rendered in the last second.\n"
         "# TYPE arcomp_frames_per_second gauge\n"
      << "arcomp_frames_per_second " << framesInLastSecond() << '\n'
      << "# HELP arcomp_camera_up 1 while the camera streams, 0 otherwise.\n"
         "# TYPE arcomp_camera_up gauge\n";
    for (const auto& [name, camera] : cameras_)
        s << "arcomp_camera_up{camera=\"" << labelValue(name) << "\"} "
          << (camera.state.status == SourceStatus::Streaming ? 1 : 0) << '\n';
    s << "# HELP arcomp_camera_dropped_frames_total Frames a camera delivered that the station was too slow to show.\n"
         "# TYPE arcomp_camera_dropped_frames_total counter\n";
    for (const auto& [name, camera] : cameras_)
        s << "arcomp_camera_dropped_frames_total{camera=\"" << labelValue(name) << "\"} " << camera.drops << '\n';
    s << "# HELP arcomp_camera_reconnects_total Times a lost camera came back.\n"
         "# TYPE arcomp_camera_reconnects_total counter\n";
    for (const auto& [name, camera] : cameras_)
        s << "arcomp_camera_reconnects_total{camera=\"" << labelValue(name) << "\"} " << camera.reconnects << '\n';
    s << "# HELP arcomp_people Visitors the station follows, this frame.\n"
         "# TYPE arcomp_people gauge\n"
      << "arcomp_people " << people_ << '\n';
    const auto labels = [](const OutputStatus& o) {
        return "{output=\"" + labelValue(o.kind) + "\",target=\"" + labelValue(o.target) + "\"}";
    };
    s << "# HELP arcomp_output_messages_sent_total Show-control messages (OSC and TUIO bundles, MQTT messages) sent.\n"
         "# TYPE arcomp_output_messages_sent_total counter\n";
    for (const OutputStatus& o : outputs_)
        s << "arcomp_output_messages_sent_total" << labels(o) << ' ' << o.sent << '\n';
    s << "# HELP arcomp_output_messages_dropped_total Show-control messages dropped: the socket was full, the broker "
         "away.\n"
         "# TYPE arcomp_output_messages_dropped_total counter\n";
    for (const OutputStatus& o : outputs_)
        s << "arcomp_output_messages_dropped_total" << labels(o) << ' ' << o.dropped << '\n';
    s << "# HELP arcomp_output_up 1 while an output sends (MQTT: while connected to its broker), 0 otherwise.\n"
         "# TYPE arcomp_output_up gauge\n";
    for (const OutputStatus& o : outputs_)
        s << "arcomp_output_up" << labels(o) << ' ' << (o.state == "sending" || o.state == "connected" ? 1 : 0) << '\n';
    s << "# HELP arcomp_zone_people Visitors in each zone, this frame.\n"
         "# TYPE arcomp_zone_people gauge\n";
    for (const ZoneCount& z : zones_)
        s << "arcomp_zone_people{zone=\"" << labelValue(z.name) << "\"} " << z.people << '\n';
    s << "# HELP arcomp_zone_entries_total Visitors who entered each zone.\n"
         "# TYPE arcomp_zone_entries_total counter\n";
    for (const ZoneCount& z : zones_)
        s << "arcomp_zone_entries_total{zone=\"" << labelValue(z.name) << "\"} " << z.entries << '\n';
    s << "# HELP arcomp_trigger_fired_total Times each trigger fired.\n"
         "# TYPE arcomp_trigger_fired_total counter\n";
    for (const TriggerStatus& t : triggers_)
        s << "arcomp_trigger_fired_total{trigger=\"" << labelValue(t.name) << "\"} " << t.fired << '\n';
    s << "# HELP arcomp_cues_total Cues from show control, done (accepted) or not (refused: sender, packet, name).\n"
         "# TYPE arcomp_cues_total counter\n"
      << "arcomp_cues_total{result=\"accepted\"} " << cuesAccepted_ << '\n'
      << "arcomp_cues_total{result=\"refused\"} " << cuesRefused_ << '\n';
    const auto streamLabel = [](const StreamStatus& st) { return "{stream=\"" + labelValue(st.name) + "\"} "; };
    const auto streamFamily = [&](const char* name, const char* type, const char* help, auto value) {
        s << "# HELP " << name << ' ' << help << "\n# TYPE " << name << ' ' << type << '\n';
        for (const StreamStatus& st : streams_) s << name << streamLabel(st) << value(st) << '\n';
    };
    streamFamily("arcomp_stream_up", "gauge", "1 while a stream's pipeline runs, 0 while it waits to retry.",
                 [](const StreamStatus& st) { return st.state == StreamState::Streaming ? 1 : 0; });
    streamFamily("arcomp_stream_frames_total", "counter", "Composited frames given to each stream.",
                 [](const StreamStatus& st) { return st.framesIn; });
    streamFamily("arcomp_stream_dropped_frames_total", "counter",
                 "Frames a stream did not take: its encoder queue full, or no pipeline running.",
                 [](const StreamStatus& st) { return st.dropped; });
    streamFamily("arcomp_stream_packets_dropped_total", "counter",
                 "Packets SRT gave up as too late, and access units an RTSP client's queue had no room for: a receiver "
                 "that stops reading.",
                 [](const StreamStatus& st) { return st.packetsDropped; });
    streamFamily("arcomp_stream_reconnects_total", "counter", "Pipelines built again after a failure.",
                 [](const StreamStatus& st) { return st.reconnects; });
    streamFamily("arcomp_stream_clients", "gauge", "RTSP clients playing a stream now (0 for SRT).",
                 [](const StreamStatus& st) { return st.clients; });
    streamFamily("arcomp_stream_bitrate_kbps", "gauge", "Encoded bitrate over about the last second.",
                 [](const StreamStatus& st) { return st.kbps; });
    s << "# HELP arcomp_errors_total Errors the station reported and recovered from.\n"
         "# TYPE arcomp_errors_total counter\n"
      << "arcomp_errors_total " << errors_ << '\n';
    return s.str();
}

}  // namespace arcomp
