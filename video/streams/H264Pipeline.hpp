#pragma once
// One GStreamer pipeline that takes composited RGBA frames and sends them
// on as H.264: appsrc, colour conversion and scaling, the encoder, then a
// tail that the owner gives (a muxer and a file, an SRT sink, ...).
//
// push() copies the frame into the pipeline's queue and returns: the
// encoder and the network run on GStreamer's threads. When the queue is
// full (a slow encoder, a stalled receiver) a Drop pipeline drops the frame
// and counts it, so the kiosk never waits; a Wait pipeline waits, for a
// replay that must keep every frame. Errors are read from the bus without
// waiting (poll()) and kept, never thrown mid-show.
//
//   H264Pipeline p("out/a.mp4", settings, {768, 576, 25.0},
//                  {{"mp4mux", {{"fragment-duration", "1000"}}}, {"filesink", {{"location", "out/a.mp4"}}}},
//                  WhenFull::Wait);   // throws VideoError naming a missing element
//   p.push(rgba.data());              // width * height * 4 bytes, rows top first
//   p.close();                        // end of stream: the file is finished

#include "video/streams/H264Settings.hpp"

#include <atomic>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

using GstElement = struct _GstElement;
using GstBufferPool = struct _GstBufferPool;

namespace arcomp {

struct ElementSpec {
    std::string factory;
    // Set through GStreamer's own parsing of property values (numbers,
    // enums by nick, booleans), as gst-launch does.
    std::vector<std::pair<std::string, std::string>> properties{};
};

struct RawVideo {
    int width = 0;
    int height = 0;
    double fps = 25.0;
};

enum class WhenFull { Drop, Wait };

enum class PipelineState { Running, Failed, Closed };

class H264Pipeline {
public:
    // Builds and starts the pipeline. Throws VideoError, named by `name`,
    // when an element is missing (with its package) or the pipeline cannot
    // start (a folder not writable, a port taken).
    H264Pipeline(std::string name, const H264Settings& settings, RawVideo input, const std::vector<ElementSpec>& tail,
                 WhenFull whenFull, int queueFrames = 8);
    ~H264Pipeline();
    H264Pipeline(const H264Pipeline&) = delete;
    H264Pipeline& operator=(const H264Pipeline&) = delete;

    // `rgba`: input.width * input.height * 4 bytes. False when the frame was
    // not taken (queue full, or the pipeline failed or closed): counted in
    // dropped(). Each frame, taken or not, moves the stream's clock by one
    // frame, so drops leave gaps in time rather than speeding it up.
    bool push(const std::uint8_t* rgba);
    // Reads the bus without waiting; a failure moves state() to Failed.
    void poll();
    // Ends the stream and waits up to `seconds` for the tail to finish it
    // (a file's index, a last packet), then `lingerSeconds` more before the
    // tail's sockets close: a network sink has sent its last packets once
    // it has rendered them, but they may still need to be sent again.
    // Safe to call twice; never throws.
    void close(double seconds = 5.0, double lingerSeconds = 0.0);

    PipelineState state() const { return state_; }
    const std::string& error() const { return error_; }
    const std::string& name() const { return name_; }
    const std::string& encoder() const { return encoder_; }
    const std::string& warning() const { return warning_; }
    std::uint64_t framesIn() const { return framesIn_; }
    std::uint64_t dropped() const { return dropped_; }
    // Encoded frames and bytes that left the encoder (GStreamer's thread).
    std::uint64_t framesEncoded() const { return counters_.frames.load(std::memory_order_relaxed); }
    std::uint64_t bytesEncoded() const { return counters_.bytes.load(std::memory_order_relaxed); }
    // An unsigned integer field of the last element's "stats" structure
    // (srtsink's packets-sent-dropped, ...), summed over its receivers
    // where it keeps one structure each; 0 where there is none.
    std::uint64_t sinkStat(const char* field) const;
    // The tail's last element, for an owner that takes the encoded stream
    // itself (an appsink feeding an RTSP server).
    GstElement* tailElement() const { return sink_; }

    struct Counters {
        std::atomic<std::uint64_t> frames{0};
        std::atomic<std::uint64_t> bytes{0};
    };

private:
    void fail(std::string why);

    std::string name_;
    RawVideo input_;
    WhenFull whenFull_;
    std::size_t frameBytes_;
    std::uint64_t queueBytes_;
    int fpsNum_ = 25, fpsDen_ = 1;
    GstElement* pipeline_ = nullptr;
    GstElement* source_ = nullptr;
    GstElement* sink_ = nullptr;
    GstBufferPool* pool_ = nullptr;
    std::string encoder_, warning_, error_;
    PipelineState state_ = PipelineState::Running;
    std::uint64_t framesIn_ = 0, dropped_ = 0;
    Counters counters_;
};

}  // namespace arcomp
