#include "video/streams/RtspServer.hpp"

#include "video/pixels/VideoError.hpp"
#include "video/streams/GstRuntime.hpp"

#include <gst/app/gstappsink.h>
#include <gst/app/gstappsrc.h>
#include <gst/gst.h>
#include <gst/rtsp-server/rtsp-server.h>
#include <gst/video/video-event.h>

#include <cstdlib>
#include <map>

namespace arcomp {

namespace {

// The media's appsrc holds at most this much before access units are dropped.
constexpr guint64 kMediaQueueBytes = 4u << 20;

constexpr const char* kAnonymous = "anonymous";

// A media for each client of a mount, fed access units that are already
// encoded; do-timestamp stamps each as it arrives, so the media's clock
// is its own whatever the station's pipeline was doing before it. SPS and
// PPS go before each keyframe once, by the parser: the payloader's own
// repeat puts them before each slice of a keyframe, and FFmpeg's clients
// (ffplay, OBS) then split the frame in two and smear until the next one.
constexpr const char* kLaunch =
    "( appsrc name=feed is-live=true format=time do-timestamp=true ! h264parse config-interval=-1 ! "
    "video/x-h264,stream-format=byte-stream,alignment=au ! rtph264pay name=pay0 pt=96 )";

struct ServerState {
    std::mutex lock;
    std::vector<RtspMount*> mounts;
    std::map<GstRTSPClient*, RtspMount*> playing;
};

RtspMount* mountOf(const ServerState& state, const GstRTSPUrl* url) {
    if (url == nullptr || url->abspath == nullptr) return nullptr;
    const std::string path = url->abspath;
    for (RtspMount* m : state.mounts) {
        const std::string& p = m->spec().path;
        if (path.compare(0, p.size(), p) == 0 && (path.size() == p.size() || path[p.size()] == '/')) return m;
    }
    return nullptr;
}

void clientGone(GstRTSPClient* client, ServerState* state) {
    std::lock_guard lock(state->lock);
    if (auto it = state->playing.find(client); it != state->playing.end()) {
        it->second->clientLeft();
        state->playing.erase(it);
    }
}

void onPlay(GstRTSPClient* client, GstRTSPContext* context, ServerState* state) {
    std::lock_guard lock(state->lock);
    RtspMount* m = mountOf(*state, context->uri);
    if (m != nullptr && state->playing.emplace(client, m).second) m->clientJoined();
}

void onTeardown(GstRTSPClient* client, GstRTSPContext*, ServerState* state) { clientGone(client, state); }

void onClientConnected(GstRTSPServer*, GstRTSPClient* client, ServerState* state) {
    g_signal_connect(client, "play-request", G_CALLBACK(onPlay), state);
    g_signal_connect(client, "teardown-request", G_CALLBACK(onTeardown), state);
    g_signal_connect(client, "closed", G_CALLBACK(clientGone), state);
}

void onMediaConfigure(GstRTSPMediaFactory*, GstRTSPMedia* media, RtspMount* mount) { mount->mediaConfigured(media); }

void onMediaUnprepared(GstRTSPMedia* media, RtspMount* mount) { mount->mediaUnprepared(media); }

GstFlowReturn onSample(GstAppSink* sink, gpointer mount) {
    static_cast<RtspMount*>(mount)->feed(GST_ELEMENT(sink));
    return GST_FLOW_OK;
}

GstRTSPFilterResult removeClient(GstRTSPServer*, GstRTSPClient*, gpointer) { return GST_RTSP_FILTER_REMOVE; }

void deleteState(gpointer state) { delete static_cast<ServerState*>(state); }

}  // namespace

RtspMount::~RtspMount() {
    std::lock_guard lock(lock_);
    for (const ClientMedia& c : medias_) release(c);
}

void RtspMount::release(const ClientMedia& c) {
    g_signal_handlers_disconnect_by_data(c.media, this);
    gst_object_unref(c.source);
    g_object_unref(c.media);
}

void RtspMount::listenTo(GstElement* appsink) {
    GstAppSinkCallbacks callbacks{};
    callbacks.new_sample = &onSample;
    gst_app_sink_set_callbacks(GST_APP_SINK(appsink), &callbacks, this, nullptr);
}

void RtspMount::mediaConfigured(GstRTSPMedia* media) {
    GstElement* bin = gst_rtsp_media_get_element(media);
    GstElement* source = gst_bin_get_by_name(GST_BIN(bin), "feed");
    gst_object_unref(bin);
    if (source == nullptr) std::abort();  // kLaunch names it
    g_object_set(source, "max-bytes", kMediaQueueBytes, "block", FALSE, nullptr);
    std::lock_guard lock(lock_);
    medias_.push_back({GST_RTSP_MEDIA(g_object_ref(media)), source});
    g_signal_connect(media, "unprepared", G_CALLBACK(onMediaUnprepared), this);
    wantsKeyframe_ = true;
}

void RtspMount::mediaUnprepared(GstRTSPMedia* media) {
    std::lock_guard lock(lock_);
    std::erase_if(medias_, [&](const ClientMedia& c) {
        if (c.media != media) return false;
        release(c);
        return true;
    });
}

void RtspMount::feed(GstElement* appsink) {
    GstSample* sample = gst_app_sink_pull_sample(GST_APP_SINK(appsink));
    if (sample == nullptr) return;
    if (wantsKeyframe_.exchange(false))
        gst_element_send_event(appsink, gst_video_event_new_upstream_force_key_unit(GST_CLOCK_TIME_NONE, TRUE, 0));
    GstBuffer* buffer = gst_sample_get_buffer(sample);
    const bool keyframe = buffer != nullptr && !GST_BUFFER_FLAG_IS_SET(buffer, GST_BUFFER_FLAG_DELTA_UNIT);
    std::lock_guard lock(lock_);
    for (ClientMedia& c : medias_) {
        // A client's media starts at a keyframe: the units before it would
        // decode to grey and smears on the client's screen.
        c.started = c.started || keyframe;
        if (!c.started || buffer == nullptr) continue;
        auto* source = GST_APP_SRC(c.source);
        if (gst_app_src_get_current_level_bytes(source) >= kMediaQueueBytes) {
            ++dropped_;
            continue;
        }
        gst_app_src_set_caps(source, gst_sample_get_caps(sample));
        // A copy shares the memory; without the station's timestamps the
        // media stamps it with its own clock.
        GstBuffer* unit = gst_buffer_copy(buffer);
        GST_BUFFER_PTS(unit) = GST_CLOCK_TIME_NONE;
        GST_BUFFER_DTS(unit) = GST_CLOCK_TIME_NONE;
        gst_app_src_push_buffer(source, unit);
    }
    gst_sample_unref(sample);
}

RtspServer::RtspServer(std::string host, int port, const std::vector<RtspMountSpec>& mounts)
    : host_(std::move(host)), port_(port) {
    initGstreamer();
    const std::string where = "rtsp://" + host_ + ":" + std::to_string(port_);
    auto* state = new ServerState;
    server_ = gst_rtsp_server_new();
    g_object_set_data_full(G_OBJECT(server_), "arcomp-state", state, deleteState);
    gst_rtsp_server_set_address(server_, host_.c_str());
    gst_rtsp_server_set_service(server_, std::to_string(port_).c_str());
    g_signal_connect(server_, "client-connected", G_CALLBACK(onClientConnected), state);

    // Clients without credentials carry the anonymous role; a mount with
    // credentials grants its own role only.
    GstRTSPAuth* auth = gst_rtsp_auth_new();
    GstRTSPToken* anonymous = gst_rtsp_token_new(GST_RTSP_TOKEN_MEDIA_FACTORY_ROLE, G_TYPE_STRING, kAnonymous, nullptr);
    gst_rtsp_auth_set_default_token(auth, anonymous);
    gst_rtsp_token_unref(anonymous);
    GstRTSPMountPoints* points = gst_rtsp_server_get_mount_points(server_);
    for (const RtspMountSpec& spec : mounts) {
        for (const auto& m : mounts_)
            if (m->spec().path == spec.path) {
                g_object_unref(points);
                g_object_unref(auth);
                gst_object_unref(server_);
                throw VideoError(where + spec.path, "path", "served twice on one port");
            }
        mounts_.push_back(std::make_unique<RtspMount>(spec));
        RtspMount* mount = mounts_.back().get();
        state->mounts.push_back(mount);
        GstRTSPMediaFactory* factory = gst_rtsp_media_factory_new();
        gst_rtsp_media_factory_set_launch(factory, kLaunch);
        g_signal_connect(factory, "media-configure", G_CALLBACK(onMediaConfigure), mount);
        std::string role = kAnonymous;
        if (!spec.user.empty()) {
            role = "viewer" + spec.path;  // a GStreamer structure name: no spaces
            GstRTSPToken* token =
                gst_rtsp_token_new(GST_RTSP_TOKEN_MEDIA_FACTORY_ROLE, G_TYPE_STRING, role.c_str(), nullptr);
            gchar* basic = gst_rtsp_auth_make_basic(spec.user.c_str(), spec.password.c_str());
            gst_rtsp_auth_add_basic(auth, basic, token);
            g_free(basic);
            gst_rtsp_token_unref(token);
            // Anonymous clients may find the mount but not play it: they
            // are answered 401 with a challenge, and a player asks for the
            // credentials (no access at all would answer 404).
            gst_rtsp_media_factory_add_role(factory, kAnonymous, GST_RTSP_PERM_MEDIA_FACTORY_ACCESS, G_TYPE_BOOLEAN,
                                            TRUE, GST_RTSP_PERM_MEDIA_FACTORY_CONSTRUCT, G_TYPE_BOOLEAN, FALSE,
                                            nullptr);
        }
        gst_rtsp_media_factory_add_role(factory, role.c_str(), GST_RTSP_PERM_MEDIA_FACTORY_ACCESS, G_TYPE_BOOLEAN, TRUE,
                                        GST_RTSP_PERM_MEDIA_FACTORY_CONSTRUCT, G_TYPE_BOOLEAN, TRUE, nullptr);
        gst_rtsp_mount_points_add_factory(points, spec.path.c_str(), factory);
    }
    g_object_unref(points);
    gst_rtsp_server_set_auth(server_, auth);
    g_object_unref(auth);

    context_ = g_main_context_new();
    sourceId_ = gst_rtsp_server_attach(server_, context_);
    if (sourceId_ == 0) {
        gst_object_unref(server_);
        g_main_context_unref(context_);
        throw VideoError(where, "address",
                         "cannot be bound (is another program serving on port " + std::to_string(port_) + "?)");
    }
    loop_ = g_main_loop_new(context_, FALSE);
    thread_ = std::thread([this] {
        g_main_context_push_thread_default(context_);
        g_main_loop_run(loop_);
        g_main_context_pop_thread_default(context_);
    });
}

RtspServer::~RtspServer() {
    // Say goodbye to the clients, stop listening, then end the loop.
    gst_rtsp_server_client_filter(server_, removeClient, nullptr);
    if (GSource* source = g_main_context_find_source_by_id(context_, sourceId_)) g_source_destroy(source);
    // Quit from inside the loop: a quit before the thread has entered it would be lost.
    GSource* quit = g_idle_source_new();
    g_source_set_callback(
        quit,
        [](gpointer loop) {
            g_main_loop_quit(static_cast<GMainLoop*>(loop));
            return G_SOURCE_REMOVE;
        },
        loop_, nullptr);
    g_source_attach(quit, context_);
    g_source_unref(quit);
    if (thread_.joinable()) thread_.join();
    gst_object_unref(server_);
    g_main_loop_unref(loop_);
    g_main_context_unref(context_);
}

RtspMount& RtspServer::mount(const std::string& path) {
    for (const auto& m : mounts_)
        if (m->spec().path == path) return *m;
    std::abort();  // the owner mounts every path it asks for
}

}  // namespace arcomp
