#include "video/streams/StreamOutputs.hpp"

#include "video/pixels/VideoError.hpp"
#include "video/streams/GstRuntime.hpp"

#include <algorithm>
#include <atomic>
#include <map>

namespace arcomp {

namespace {

using Clock = std::chrono::steady_clock;
constexpr std::chrono::milliseconds kFirstBackoff{500};
constexpr std::chrono::milliseconds kLongestBackoff{10000};
constexpr std::chrono::milliseconds kSupervisorTick{50};

std::vector<ElementSpec> srtTail(const StreamSpec& s) {
    // The uri first: setting it puts srtsink's other settings back to their defaults.
    std::vector<std::pair<std::string, std::string>> sink{
        {"uri", "srt://" + s.host + ":" + std::to_string(s.port) + (s.listener ? "?mode=listener" : "")},
        // Without a poll timeout a sink waiting on its socket cannot be stopped.
        {"poll-timeout", "100"},
        {"latency", std::to_string(s.latencyMs)},
        // The supervisor reconnects, with backoff and counted; the sink's
        // own reconnecting would hold its thread in connect().
        {"auto-reconnect", "false"},
        // Frames leave as they are encoded; SRT paces them to receivers.
        {"sync", "false"},
        // A listener without a receiver drops what it is given.
        {"wait-for-connection", "false"},
    };
    if (!s.passphrase.empty()) sink.emplace_back("passphrase", s.passphrase);
    // Seven 188-byte TS packets to a buffer: one SRT live-mode payload
    // (1316 bytes); a larger buffer would not fit a message.
    return {{"mpegtsmux", {{"alignment", "7"}}}, {"srtsink", std::move(sink)}};
}

// Access units go to the RTSP server's mount, taken one by one; a few in
// hand at most, so that a mount that is slow to take them drops, never the
// encoder waits.
std::vector<ElementSpec> rtspTail() {
    return {{"appsink", {{"sync", "false"}, {"max-buffers", "4"}, {"drop", "true"}}}};
}

std::vector<ElementSpec> tailOf(const StreamSpec& s) {
    return s.protocol == StreamProtocol::Rtsp ? rtspTail() : srtTail(s);
}

std::string serverKey(const StreamSpec& s) { return s.host + ":" + std::to_string(s.port); }

}  // namespace

std::string missingStreamElements(const StreamSpec& spec) {
    if (const EncoderChoice c = chooseH264Encoder(spec.encoding.encoder); c.element.empty()) return c.warning;
    std::vector<std::string> needed{"h264parse"};
    for (const ElementSpec& e : tailOf(spec)) needed.push_back(e.factory);
    if (spec.protocol == StreamProtocol::Rtsp) needed.insert(needed.end(), {"appsrc", "rtph264pay"});
    for (const std::string& e : needed)
        if (!hasGstElement(e)) return "GStreamer element " + e + " missing (install " + packageOfGstElement(e) + ")";
    return "";
}

struct StreamOutputs::Stream {
    StreamSpec spec;
    std::vector<ElementSpec> tail;
    RtspMount* mount = nullptr;  // RTSP: where the access units go
    std::mutex lock;             // the frame only tries it
    std::unique_ptr<H264Pipeline> pipeline;
    // Counted by the frame (framesIn, dropped) and by the supervisor; read by status().
    std::atomic<std::uint64_t> framesIn{0}, dropped{0}, reconnects{0};
    std::atomic<std::uint64_t> bytesBefore{0};  // of pipelines torn down
    std::atomic<std::uint64_t> bytesTotal{0};   // as the supervisor last counted
    std::atomic<std::uint64_t> packetsBefore{0}, packetsTotal{0};
    std::atomic<bool> retrying{false};
    // The supervisor's own.
    Clock::time_point retryAt{};
    std::chrono::milliseconds backoff = kFirstBackoff;
    std::uint64_t rateBytes = 0;
    Clock::time_point rateSince = Clock::now();
    mutable std::mutex textLock;  // lastError, warning, kbps
    std::string lastError, warning;
    double kbps = 0.0;
};

StreamOutputs::StreamOutputs(const std::vector<StreamSpec>& specs, RawVideo input) : input_(input) {
    for (const StreamSpec& spec : specs)
        if (const std::string missing = missingStreamElements(spec); !missing.empty())
            throw VideoError(spec.name, spec.describe(), missing);
    startRtspServers(specs);
    for (const StreamSpec& spec : specs) {
        auto s = std::make_unique<Stream>();
        s->spec = spec;
        s->tail = tailOf(spec);
        if (spec.protocol == StreamProtocol::Rtsp)
            for (const auto& server : rtspServers_)
                if (server->host() == spec.host && server->port() == spec.port) s->mount = &server->mount(spec.path);
        try {
            s->pipeline = build(*s);
            s->warning = s->pipeline->warning();
        } catch (const VideoError& e) {
            // A listener that cannot bind will not bind later either.
            if (spec.listener) throw;
            s->lastError = e.what();
            s->retrying = true;
            s->retryAt = Clock::now() + s->backoff;
        }
        streams_.push_back(std::move(s));
    }
    if (!streams_.empty()) supervisor_ = std::thread([this] { supervise(); });
}

StreamOutputs::~StreamOutputs() { close(); }

void StreamOutputs::startRtspServers(const std::vector<StreamSpec>& specs) {
    std::map<std::string, std::vector<RtspMountSpec>> mounts;
    for (const StreamSpec& spec : specs)
        if (spec.protocol == StreamProtocol::Rtsp)
            mounts[serverKey(spec)].push_back({spec.path, spec.user, spec.password});
    for (const StreamSpec& spec : specs) {
        auto it = mounts.find(serverKey(spec));
        if (spec.protocol != StreamProtocol::Rtsp || it == mounts.end()) continue;
        try {
            rtspServers_.push_back(std::make_unique<RtspServer>(spec.host, spec.port, it->second));
        } catch (const VideoError& e) {
            throw VideoError(spec.name, spec.describe(), e.what());
        }
        mounts.erase(it);
    }
}

std::unique_ptr<H264Pipeline> StreamOutputs::build(const Stream& s) const {
    auto pipeline = std::make_unique<H264Pipeline>(s.spec.name, s.spec.encoding, input_, s.tail, WhenFull::Drop,
                                                   s.spec.queueFrames);
    if (s.mount != nullptr) s.mount->listenTo(pipeline->tailElement());
    return pipeline;
}

void StreamOutputs::push(const std::uint8_t* rgba) {
    for (const auto& s : streams_) {
        s->framesIn.fetch_add(1, std::memory_order_relaxed);
        std::unique_lock lock(s->lock, std::try_to_lock);
        if (!lock || !s->pipeline || !s->pipeline->push(rgba)) s->dropped.fetch_add(1, std::memory_order_relaxed);
    }
}

void StreamOutputs::supervise() {
    std::unique_lock wakeLock(wakeMutex_);
    while (!stopping_) {
        wake_.wait_for(wakeLock, kSupervisorTick);
        if (stopping_) break;
        wakeLock.unlock();
        const Clock::time_point now = Clock::now();
        for (const auto& s : streams_) {
            std::unique_ptr<H264Pipeline> failed;
            std::uint64_t bytes = s->bytesBefore.load();
            std::uint64_t packets = s->packetsBefore.load();
            {
                std::lock_guard lock(s->lock);
                if (s->pipeline) {
                    s->pipeline->poll();
                    bytes += s->pipeline->bytesEncoded();
                    packets += s->pipeline->sinkStat("packets-sent-dropped");
                    if (s->pipeline->state() == PipelineState::Failed) failed = std::move(s->pipeline);
                }
            }
            s->bytesTotal = bytes;
            s->packetsTotal = std::max(s->packetsTotal.load(), packets);
            if (failed) {
                s->bytesBefore += failed->bytesEncoded();
                s->packetsBefore = s->packetsTotal.load();
                {
                    std::lock_guard text(s->textLock);
                    s->lastError = failed->name() + ": " + failed->error();
                }
                failed.reset();  // to NULL state, off the frame's thread
                s->retrying = true;
                s->retryAt = now + s->backoff;
                s->backoff = std::min(s->backoff * 2, kLongestBackoff);
            } else if (s->retrying && now >= s->retryAt) {
                try {
                    auto fresh = build(*s);
                    std::lock_guard lock(s->lock);
                    s->pipeline = std::move(fresh);
                    s->retrying = false;
                    ++s->reconnects;
                } catch (const VideoError& e) {
                    std::lock_guard text(s->textLock);
                    s->lastError = e.what();
                    s->retryAt = now + s->backoff;
                    s->backoff = std::min(s->backoff * 2, kLongestBackoff);
                }
            }
            if (now - s->rateSince >= std::chrono::seconds(1)) {
                const double seconds = std::chrono::duration<double>(now - s->rateSince).count();
                std::lock_guard text(s->textLock);
                s->kbps = static_cast<double>(bytes - std::min(bytes, s->rateBytes)) * 8.0 / 1000.0 / seconds;
                s->rateBytes = bytes;
                s->rateSince = now;
                // A pipeline that has run a while without failing has
                // reconnected for good: the next failure starts the backoff over.
                if (!s->retrying && s->kbps > 0.0) s->backoff = kFirstBackoff;
            }
        }
        wakeLock.lock();
    }
}

std::vector<StreamStatus> StreamOutputs::status() const {
    std::vector<StreamStatus> out;
    out.reserve(streams_.size());
    for (const auto& s : streams_) {
        StreamStatus st;
        st.name = s->spec.name;
        st.target = s->spec.describe();
        st.state = s->retrying ? StreamState::Retrying : StreamState::Streaming;
        st.framesIn = s->framesIn;
        st.dropped = s->dropped;
        st.reconnects = s->reconnects;
        st.bytes = s->bytesTotal;
        st.packetsDropped = s->packetsTotal;
        if (s->mount != nullptr) {
            st.clients = s->mount->clients();
            st.packetsDropped += s->mount->dropped();
        }
        std::lock_guard text(s->textLock);
        st.kbps = s->kbps;
        st.lastError = s->lastError;
        st.warning = s->warning;
        out.push_back(std::move(st));
    }
    return out;
}

void StreamOutputs::close() {
    {
        std::lock_guard lock(wakeMutex_);
        if (stopping_) return;
        stopping_ = true;
    }
    wake_.notify_all();
    if (supervisor_.joinable()) supervisor_.join();
    for (const auto& s : streams_) {
        std::lock_guard lock(s->lock);
        // SRT: three latencies, time for the receiver to ask for the last packets again.
        const double linger =
            s->spec.protocol == StreamProtocol::Srt ? std::min(1.0, 3.0 * s->spec.latencyMs / 1000.0) : 0.0;
        if (s->pipeline) s->pipeline->close(1.0, linger);
        s->mount = nullptr;
    }
    rtspServers_.clear();
}

}  // namespace arcomp
