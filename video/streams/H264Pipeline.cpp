#include "video/streams/H264Pipeline.hpp"

#include "video/pixels/VideoError.hpp"
#include "video/streams/GstRuntime.hpp"

#include <gst/app/gstappsrc.h>
#include <gst/gst.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

namespace arcomp {

namespace {

GstElement* make(const std::string& pipelineName, const ElementSpec& spec) {
    GstElement* e = gst_element_factory_make(spec.factory.c_str(), nullptr);
    if (e == nullptr)
        throw VideoError(pipelineName, "GStreamer element " + spec.factory,
                         "missing on this machine (install " + packageOfGstElement(spec.factory) + ")");
    for (const auto& [key, value] : spec.properties) {
        if (g_object_class_find_property(G_OBJECT_GET_CLASS(e), key.c_str()) == nullptr) {
            gst_object_unref(e);
            throw VideoError(pipelineName, "GStreamer element " + spec.factory, "has no property " + key);
        }
        gst_util_set_object_arg(G_OBJECT(e), key.c_str(), value.c_str());
    }
    return e;
}

// The first of `names` that `element` has, set to `value`; encoders name
// their bitrate and keyframe distance differently.
void setFirstOf(GstElement* element, std::initializer_list<const char*> names, const std::string& value) {
    for (const char* name : names)
        if (g_object_class_find_property(G_OBJECT_GET_CLASS(element), name) != nullptr) {
            gst_util_set_object_arg(G_OBJECT(element), name, value.c_str());
            return;
        }
}

std::string messageText(GstMessage* message) {
    GError* error = nullptr;
    gchar* debug = nullptr;
    if (GST_MESSAGE_TYPE(message) == GST_MESSAGE_ERROR)
        gst_message_parse_error(message, &error, &debug);
    else
        gst_message_parse_warning(message, &error, &debug);
    std::string text = std::string(GST_OBJECT_NAME(GST_MESSAGE_SRC(message))) + ": " +
                       (error != nullptr ? error->message : "unknown error");
    g_clear_error(&error);
    g_free(debug);
    return text;
}

GstPadProbeReturn countEncoded(GstPad*, GstPadProbeInfo* info, gpointer counters) {
    auto* c = static_cast<H264Pipeline::Counters*>(counters);
    if (GstBuffer* b = GST_PAD_PROBE_INFO_BUFFER(info)) {
        c->frames.fetch_add(1, std::memory_order_relaxed);
        c->bytes.fetch_add(gst_buffer_get_size(b), std::memory_order_relaxed);
    }
    return GST_PAD_PROBE_OK;
}

}  // namespace

H264Pipeline::H264Pipeline(std::string name, const H264Settings& settings, RawVideo input,
                           const std::vector<ElementSpec>& tail, WhenFull whenFull, int queueFrames)
    : name_(std::move(name)), input_(input), whenFull_(whenFull),
      frameBytes_(static_cast<std::size_t>(input.width) * static_cast<std::size_t>(input.height) * 4) {
    initGstreamer();
    if (input.width <= 0 || input.height <= 0 || !(input.fps > 0.0))
        throw VideoError(name_, "input", "expected a positive size and frame rate");
    queueBytes_ = frameBytes_ * static_cast<std::uint64_t>(std::max(1, queueFrames));
    gst_util_double_to_fraction(input.fps, &fpsNum_, &fpsDen_);

    const EncoderChoice choice = chooseH264Encoder(settings.encoder);
    if (choice.element.empty()) throw VideoError(name_, "encoder", choice.warning);
    encoder_ = choice.element;
    warning_ = choice.warning;
    const PictureSize out = encodedSize(settings, {input.width, input.height});
    const int keyframe = std::max(1, static_cast<int>(std::lround(settings.keyframeSeconds * input.fps)));

    std::vector<ElementSpec> chain{{"appsrc"},     {"videoconvert"}, {"videoscale"},
                                   {"capsfilter"}, {encoder_},       {"h264parse"}};
    chain.insert(chain.end(), tail.begin(), tail.end());
    pipeline_ = gst_pipeline_new(nullptr);
    std::vector<GstElement*> elements;
    try {
        for (const ElementSpec& spec : chain) {
            elements.push_back(make(name_, spec));
            gst_bin_add(GST_BIN(pipeline_), elements.back());
        }
    } catch (...) {
        gst_object_unref(pipeline_);
        throw;
    }
    source_ = elements[0];
    sink_ = elements.back();
    GstCaps* raw =
        gst_caps_new_simple("video/x-raw", "format", G_TYPE_STRING, "RGBA", "width", G_TYPE_INT, input.width, "height",
                            G_TYPE_INT, input.height, "framerate", GST_TYPE_FRACTION, fpsNum_, fpsDen_, nullptr);
    g_object_set(source_, "caps", raw, "format", GST_FORMAT_TIME, "block", FALSE, "max-bytes", queueBytes_, nullptr);
    GstCaps* scaled = gst_caps_new_simple("video/x-raw", "format", G_TYPE_STRING, "I420", "width", G_TYPE_INT,
                                          out.width, "height", G_TYPE_INT, out.height, nullptr);
    g_object_set(elements[3], "caps", scaled, nullptr);
    gst_caps_unref(scaled);

    GstElement* encoder = elements[4];
    if (encoder_ == "x264enc") {
        gst_util_set_object_arg(G_OBJECT(encoder), "speed-preset", "veryfast");
        if (settings.lowLatency) gst_util_set_object_arg(G_OBJECT(encoder), "tune", "zerolatency");
    }
    setFirstOf(encoder, {"bitrate"}, std::to_string(settings.bitrateKbps));
    setFirstOf(encoder, {"key-int-max", "keyframe-period", "gop-size"}, std::to_string(keyframe));
    GstPad* encoded = gst_element_get_static_pad(encoder, "src");
    gst_pad_add_probe(encoded, GST_PAD_PROBE_TYPE_BUFFER, countEncoded, &counters_, nullptr);
    gst_object_unref(encoded);

    for (std::size_t i = 1; i < elements.size(); ++i)
        if (!gst_element_link(elements[i - 1], elements[i])) {
            const std::string what = chain[i - 1].factory + " to " + chain[i].factory;
            gst_caps_unref(raw);
            gst_object_unref(pipeline_);
            throw VideoError(name_, "pipeline", "cannot link " + what);
        }

    pool_ = gst_buffer_pool_new();
    GstStructure* config = gst_buffer_pool_get_config(pool_);
    gst_buffer_pool_config_set_params(config, raw, static_cast<guint>(frameBytes_), 2, 0);
    gst_buffer_pool_set_config(pool_, config);
    gst_buffer_pool_set_active(pool_, TRUE);
    gst_caps_unref(raw);

    if (gst_element_set_state(pipeline_, GST_STATE_PLAYING) == GST_STATE_CHANGE_FAILURE) {
        poll();
        const std::string why = error_.empty() ? "the pipeline did not start" : error_;
        close(0.0);
        throw VideoError(name_, "start", why);
    }
}

H264Pipeline::~H264Pipeline() {
    close();
    if (pool_ != nullptr) {
        gst_buffer_pool_set_active(pool_, FALSE);
        gst_object_unref(pool_);
    }
    if (pipeline_ != nullptr) gst_object_unref(pipeline_);
}

void H264Pipeline::fail(std::string why) {
    if (state_ != PipelineState::Running) return;
    state_ = PipelineState::Failed;
    error_ = std::move(why);
}

void H264Pipeline::poll() {
    GstBus* bus = gst_element_get_bus(pipeline_);
    while (GstMessage* m = gst_bus_pop_filtered(bus, static_cast<GstMessageType>(GST_MESSAGE_ERROR))) {
        fail(messageText(m));
        gst_message_unref(m);
    }
    gst_object_unref(bus);
}

bool H264Pipeline::push(const std::uint8_t* rgba) {
    const std::uint64_t index = framesIn_++;
    poll();
    auto* source = GST_APP_SRC(source_);
    if (whenFull_ == WhenFull::Wait) {
        GstBus* bus = gst_element_get_bus(pipeline_);
        while (state_ == PipelineState::Running && gst_app_src_get_current_level_bytes(source) >= queueBytes_)
            if (GstMessage* m = gst_bus_timed_pop_filtered(bus, 10 * GST_MSECOND, GST_MESSAGE_ERROR)) {
                fail(messageText(m));
                gst_message_unref(m);
            }
        gst_object_unref(bus);
    }
    if (state_ != PipelineState::Running || gst_app_src_get_current_level_bytes(source) >= queueBytes_) {
        ++dropped_;
        return false;
    }
    GstBuffer* buffer = nullptr;
    if (gst_buffer_pool_acquire_buffer(pool_, &buffer, nullptr) != GST_FLOW_OK) {
        ++dropped_;
        return false;
    }
    gst_buffer_fill(buffer, 0, rgba, frameBytes_);
    GST_BUFFER_PTS(buffer) =
        gst_util_uint64_scale(index, GST_SECOND * static_cast<guint64>(fpsDen_), static_cast<guint64>(fpsNum_));
    GST_BUFFER_DURATION(buffer) =
        gst_util_uint64_scale(GST_SECOND, static_cast<guint64>(fpsDen_), static_cast<guint64>(fpsNum_));
    if (gst_app_src_push_buffer(source, buffer) != GST_FLOW_OK) {
        ++dropped_;
        return false;
    }
    return true;
}

std::uint64_t H264Pipeline::sinkStat(const char* field) const {
    if (g_object_class_find_property(G_OBJECT_GET_CLASS(sink_), "stats") == nullptr) return 0;
    GstStructure* stats = nullptr;
    g_object_get(sink_, "stats", &stats, nullptr);
    if (stats == nullptr) return 0;
    const auto valueOf = [field](const GstStructure* s) -> std::uint64_t {
        const GValue* v = gst_structure_get_value(s, field);
        if (v == nullptr) return 0;
        if (G_VALUE_HOLDS_UINT64(v)) return g_value_get_uint64(v);
        if (G_VALUE_HOLDS_INT64(v)) return static_cast<std::uint64_t>(std::max<gint64>(0, g_value_get_int64(v)));
        if (G_VALUE_HOLDS_INT(v)) return static_cast<std::uint64_t>(std::max(0, g_value_get_int(v)));
        return 0;
    };
    std::uint64_t total = valueOf(stats);
    // A listener keeps one structure a receiver, in "callers".
    // GValueArray is deprecated in GLib, but it is what srtsink gives.
    G_GNUC_BEGIN_IGNORE_DEPRECATIONS
    if (const GValue* callers = gst_structure_get_value(stats, "callers");
        callers != nullptr && G_VALUE_TYPE(callers) == g_value_array_get_type()) {
        const auto* array = static_cast<const GValueArray*>(g_value_get_boxed(callers));
        for (guint i = 0; array != nullptr && i < array->n_values; ++i)
            if (const GValue* c = g_value_array_get_nth(const_cast<GValueArray*>(array), i);
                GST_VALUE_HOLDS_STRUCTURE(c))
                total += valueOf(gst_value_get_structure(c));
    }
    G_GNUC_END_IGNORE_DEPRECATIONS
    gst_structure_free(stats);
    return total;
}

void H264Pipeline::close(double seconds, double lingerSeconds) {
    if (pipeline_ == nullptr || state_ == PipelineState::Closed) return;
    if (state_ == PipelineState::Running && seconds > 0.0) {
        gst_app_src_end_of_stream(GST_APP_SRC(source_));
        GstBus* bus = gst_element_get_bus(pipeline_);
        const auto wait = static_cast<GstClockTime>(seconds * static_cast<double>(GST_SECOND));
        if (GstMessage* m = gst_bus_timed_pop_filtered(
                bus, wait, static_cast<GstMessageType>(GST_MESSAGE_EOS | GST_MESSAGE_ERROR))) {
            if (GST_MESSAGE_TYPE(m) == GST_MESSAGE_ERROR)
                fail(messageText(m));
            else if (lingerSeconds > 0.0)
                std::this_thread::sleep_for(std::chrono::duration<double>(lingerSeconds));
            gst_message_unref(m);
        } else {
            fail("the stream did not finish within " + std::to_string(seconds) + " s; stopped");
        }
        gst_object_unref(bus);
    }
    gst_element_set_state(pipeline_, GST_STATE_NULL);
    if (state_ == PipelineState::Running) state_ = PipelineState::Closed;
}

}  // namespace arcomp
