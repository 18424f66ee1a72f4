#pragma once
// An RTSP server the station runs on one address and port, so that players
// pull the composite (VLC, OBS, ffmpeg, a second screen). Each mount
// ("/lobby") is fed the H.264 access units a station's H264Pipeline has
// already encoded, so every client of a mount shares one encoder; each
// client has a media of its own, which starts at a keyframe (asked for
// when it joins) and whose queue, when the client cannot keep up, drops
// access units rather than wait. gst-rtsp-server runs on a GLib main
// loop in the server's own thread. A mount with credentials asks for HTTP
// Basic authentication; one without plays to anyone who reaches the
// address.
//
//   RtspServer server("127.0.0.1", 8554, {{"/lobby", "", ""}});  // throws VideoError: port taken
//   server.mount("/lobby").listenTo(pipeline.tailElement());      // an appsink ending the pipeline
//   server.mount("/lobby").clients();                             // playing now

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

using GstElement = struct _GstElement;
using GstRTSPServer = struct _GstRTSPServer;
using GstRTSPMedia = struct _GstRTSPMedia;
using GMainContext = struct _GMainContext;
using GMainLoop = struct _GMainLoop;

namespace arcomp {

struct RtspMountSpec {
    std::string path;            // "/lobby"
    std::string user, password;  // both empty: no authentication
};

// One path of the server: where encoded frames go in.
class RtspMount {
public:
    explicit RtspMount(RtspMountSpec spec) : spec_(std::move(spec)) {}
    ~RtspMount();
    RtspMount(const RtspMount&) = delete;
    RtspMount& operator=(const RtspMount&) = delete;

    // Takes every access unit `appsink` receives (on its streaming thread)
    // from now on, and asks its encoder for a keyframe when a client
    // joins, so that the client's picture starts at once.
    void listenTo(GstElement* appsink);
    std::uint64_t clients() const { return clients_.load(); }
    // Access units a client's media had no room for: a client that stopped
    // reading, or one on a link too slow for the stream.
    std::uint64_t dropped() const { return dropped_.load(); }
    const RtspMountSpec& spec() const { return spec_; }

    // For the server's callbacks.
    void mediaConfigured(GstRTSPMedia* media);
    void mediaUnprepared(GstRTSPMedia* media);
    void clientJoined() { ++clients_; }
    void clientLeft() { --clients_; }
    void feed(GstElement* appsink);

private:
    struct ClientMedia {
        GstRTSPMedia* media;
        GstElement* source;    // its appsrc
        bool started = false;  // has had its first keyframe
    };
    void release(const ClientMedia& c);  // with lock_ held

    RtspMountSpec spec_;
    std::mutex lock_;  // medias_
    std::vector<ClientMedia> medias_;
    std::atomic<bool> wantsKeyframe_{false};
    std::atomic<std::uint64_t> clients_{0}, dropped_{0};
};

class RtspServer {
public:
    // Binds `host`:`port` and serves `mounts`. Throws VideoError when the
    // address cannot be bound (a port taken) or two mounts share a path.
    RtspServer(std::string host, int port, const std::vector<RtspMountSpec>& mounts);
    ~RtspServer();
    RtspServer(const RtspServer&) = delete;
    RtspServer& operator=(const RtspServer&) = delete;

    // The mount at `path`; std::abort for a path not given to the constructor.
    RtspMount& mount(const std::string& path);
    const std::string& host() const { return host_; }
    int port() const { return port_; }

private:
    std::string host_;
    int port_;
    std::vector<std::unique_ptr<RtspMount>> mounts_;
    GMainContext* context_ = nullptr;
    GMainLoop* loop_ = nullptr;
    GstRTSPServer* server_ = nullptr;
    unsigned sourceId_ = 0;
    std::thread thread_;
};

}  // namespace arcomp
