#include "video/streams/GstRuntime.hpp"

#include <gst/gst.h>

#include <array>
#include <mutex>
#include <utility>

namespace arcomp {

void initGstreamer() {
    static std::once_flag once;
    std::call_once(once, [] { gst_init(nullptr, nullptr); });
}

bool hasGstElement(const std::string& factory) {
    initGstreamer();
    GstElementFactory* found = gst_element_factory_find(factory.c_str());
    if (found == nullptr) return false;
    gst_object_unref(found);
    return true;
}

std::string packageOfGstElement(const std::string& factory) {
    static constexpr std::array<std::pair<const char*, const char*>, 13> kPackages{{
        {"appsrc", "gstreamer1.0-plugins-base"},
        {"appsink", "gstreamer1.0-plugins-base"},
        {"videoconvert", "gstreamer1.0-plugins-base"},
        {"videoscale", "gstreamer1.0-plugins-base"},
        {"x264enc", "gstreamer1.0-plugins-ugly"},
        {"h264parse", "gstreamer1.0-plugins-bad"},
        {"mp4mux", "gstreamer1.0-plugins-good"},
        {"matroskamux", "gstreamer1.0-plugins-good"},
        {"mpegtsmux", "gstreamer1.0-plugins-bad"},
        {"srtsink", "gstreamer1.0-plugins-bad"},
        {"rtph264pay", "gstreamer1.0-plugins-good"},
        {"vaapih264enc", "gstreamer1.0-vaapi"},
        {"v4l2h264enc", "gstreamer1.0-plugins-good"},
    }};
    for (const auto& [element, package] : kPackages)
        if (factory == element) return package;
    return "a GStreamer plugin package";
}

}  // namespace arcomp
