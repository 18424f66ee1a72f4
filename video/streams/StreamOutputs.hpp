#pragma once
// A station's streams (SRT and RTSP), fed the composite once a
// frame without ever waiting. Each stream is an H264Pipeline behind a lock
// the frame only tries: when a supervisor thread holds it (swapping a
// failed pipeline for a new one) the frame is dropped and counted. One
// supervisor thread serves all streams: it notices a pipeline that failed
// (a receiver gone, a connection refused), tears it down and builds it
// again after a backoff of 0.5 s doubling to 10 s; no thread per attempt.
// RTSP streams on one address and port share one RtspServer.
//
//   StreamOutputs streams(specs, {768, 576, 25.0});  // throws VideoError: a missing element, a port taken
//   streams.push(rgba);                               // once a frame, never waits
//   for (const StreamStatus& s : streams.status()) ...

#include "video/streams/H264Pipeline.hpp"
#include "video/streams/RtspServer.hpp"
#include "video/streams/StreamSpec.hpp"

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace arcomp {

enum class StreamState {
    Streaming,  // the pipeline runs (a listener may have no receiver yet)
    Retrying,   // it failed; a new one is built after the backoff
};

struct StreamStatus {
    std::string name;
    std::string target;  // StreamSpec::describe()
    StreamState state = StreamState::Streaming;
    std::uint64_t framesIn = 0;
    std::uint64_t dropped = 0;     // frames not taken: queue full, a pipeline being replaced, none running
    std::uint64_t reconnects = 0;  // pipelines built again after a failure
    // Packets the protocol itself gave up on, over the stream's pipelines:
    // SRT's too late to send (a receiver that stops reading); RTSP's
    // access units the served media had no room for.
    std::uint64_t packetsDropped = 0;
    std::uint64_t clients = 0;  // RTSP: clients playing the stream now
    std::uint64_t bytes = 0;    // encoded, over all the stream's pipelines
    double kbps = 0.0;          // encoded bitrate over the last second or so
    std::string lastError;      // why it last failed; empty if it never did
    std::string warning;        // the encoder asked for is missing, ...
};

// What this machine lacks to send `spec` (an element, with its package);
// empty when it has everything.
std::string missingStreamElements(const StreamSpec& spec);

class StreamOutputs {
public:
    // Starts every stream. Throws VideoError naming the stream when an
    // element is missing or a listener or server cannot start (a port
    // taken); a caller whose receiver is not there yet is retried.
    StreamOutputs(const std::vector<StreamSpec>& specs, RawVideo input);
    ~StreamOutputs();
    StreamOutputs(const StreamOutputs&) = delete;
    StreamOutputs& operator=(const StreamOutputs&) = delete;

    // input.width * input.height * 4 bytes, to every stream; never waits.
    void push(const std::uint8_t* rgba);
    std::vector<StreamStatus> status() const;
    bool empty() const { return streams_.empty(); }
    // Ends each stream (a last packet, a goodbye to receivers); safe twice.
    void close();

private:
    struct Stream;
    void startRtspServers(const std::vector<StreamSpec>& specs);
    std::unique_ptr<H264Pipeline> build(const Stream& s) const;
    void supervise();

    RawVideo input_;
    // Before the streams: a stream's pipeline feeds a server's mount, so
    // the servers go after every pipeline.
    std::vector<std::unique_ptr<RtspServer>> rtspServers_;
    std::vector<std::unique_ptr<Stream>> streams_;
    std::thread supervisor_;
    mutable std::mutex wakeMutex_;
    std::condition_variable wake_;
    bool stopping_ = false;
};

}  // namespace arcomp
