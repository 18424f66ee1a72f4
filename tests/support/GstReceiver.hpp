#pragma once
// A real GStreamer receiver for tests: a source description up to the
// H.264 elementary stream ("srtsrc uri=srt://127.0.0.1:9000 ! tsdemux"),
// then parsed, decoded by libav and handed over as BGR frames. A receiver
// made with Reading::Stalled never takes a frame from its sink, so that
// once its few buffers are full it stops reading the network, as a
// receiver that hangs does. srtSource() writes an SRT receiver's source.
//
//   test::GstReceiver rx(test::srtSource("srt://127.0.0.1:9000?mode=listener"));
//   rx.waitForFrames(20);
//   for (const cv::Mat& f : rx.frames()) ...

#include <gst/app/gstappsink.h>
#include <gst/gst.h>
#include <opencv2/core.hpp>

#include <chrono>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace arcomp::test {

enum class Reading { Pulls, Stalled };

// srtsrc reading `uri` (then `options`, "passphrase=..."), up to the H.264
// stream. GStreamer 1.22's srtsrc waits for packets without end unless
// given a poll timeout, and stopping it then hangs for good; setting its
// uri puts every other setting back to its default, so the timeout and the
// options come after the uri.
inline std::string srtSource(const std::string& uri, const std::string& options = "") {
    return "srtsrc uri=" + uri + " poll-timeout=100" + (options.empty() ? "" : " " + options) + " ! tsdemux";
}

class GstReceiver {
public:
    explicit GstReceiver(const std::string& source, Reading reading = Reading::Pulls) {
        gst_init(nullptr, nullptr);
        const std::string description =
            source + " ! h264parse ! avdec_h264 ! videoconvert ! video/x-raw,format=BGR ! appsink name=out sync=false" +
            (reading == Reading::Stalled ? " max-buffers=1 drop=false" : "");
        GError* error = nullptr;
        pipeline_ = gst_parse_launch(description.c_str(), &error);
        if (error != nullptr) {
            const std::string why = error->message;
            g_clear_error(&error);
            if (pipeline_ != nullptr) gst_object_unref(pipeline_);
            throw std::runtime_error(description + ": " + why);
        }
        if (reading == Reading::Pulls) {
            GstElement* sink = gst_bin_get_by_name(GST_BIN(pipeline_), "out");
            GstAppSinkCallbacks callbacks{};
            callbacks.new_sample = &GstReceiver::onSample;
            gst_app_sink_set_callbacks(GST_APP_SINK(sink), &callbacks, this, nullptr);
            gst_object_unref(sink);
        }
        gst_element_set_state(pipeline_, GST_STATE_PLAYING);
    }
    ~GstReceiver() { stop(); }
    GstReceiver(const GstReceiver&) = delete;
    GstReceiver& operator=(const GstReceiver&) = delete;

    // Closes the connection as a receiver that quits does.
    void stop() {
        if (pipeline_ == nullptr) return;
        gst_element_set_state(pipeline_, GST_STATE_NULL);
        gst_object_unref(pipeline_);
        pipeline_ = nullptr;
    }

    std::vector<cv::Mat> frames() const {
        std::lock_guard lock(mutex_);
        return frames_;
    }
    std::size_t count() const {
        std::lock_guard lock(mutex_);
        return frames_.size();
    }
    // Waits for the event, up to `limit` (a ceiling for a broken run, not a
    // measured time); true when that many frames came.
    bool waitForFrames(std::size_t n, std::chrono::seconds limit = std::chrono::seconds(20)) const {
        const auto end = std::chrono::steady_clock::now() + limit;
        while (count() < n && std::chrono::steady_clock::now() < end)
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        return count() >= n;
    }

private:
    static GstFlowReturn onSample(GstAppSink* sink, gpointer self) {
        GstSample* sample = gst_app_sink_pull_sample(sink);
        if (sample == nullptr) return GST_FLOW_ERROR;
        const GstStructure* caps = gst_caps_get_structure(gst_sample_get_caps(sample), 0);
        int width = 0, height = 0;
        gst_structure_get_int(caps, "width", &width);
        gst_structure_get_int(caps, "height", &height);
        GstMapInfo map;
        GstBuffer* buffer = gst_sample_get_buffer(sample);
        if (gst_buffer_map(buffer, &map, GST_MAP_READ)) {
            const std::size_t stride = (static_cast<std::size_t>(width) * 3 + 3) & ~std::size_t{3};
            cv::Mat frame = cv::Mat(height, width, CV_8UC3, map.data, stride).clone();
            gst_buffer_unmap(buffer, &map);
            auto* receiver = static_cast<GstReceiver*>(self);
            std::lock_guard lock(receiver->mutex_);
            receiver->frames_.push_back(std::move(frame));
        }
        gst_sample_unref(sample);
        return GST_FLOW_OK;
    }

    GstElement* pipeline_ = nullptr;
    mutable std::mutex mutex_;
    std::vector<cv::Mat> frames_;
};

}  // namespace arcomp::test
