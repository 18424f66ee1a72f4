#include "video/streams/H264Settings.hpp"

#include "video/streams/GstRuntime.hpp"

#include <array>

namespace arcomp {

namespace {

constexpr std::array<const char*, 3> kHardwareEncoders{"vaapih264enc", "vah264enc", "v4l2h264enc"};

EncoderChoice x264Instead(std::string warning) {
    if (hasGstElement("x264enc")) return {"x264enc", std::move(warning)};
    return {"", "no H.264 encoder: GStreamer element x264enc missing (install gstreamer1.0-plugins-ugly)"};
}

}  // namespace

EncoderChoice chooseH264Encoder(const std::string& encoder) {
    if (encoder == "x264" || encoder == "x264enc") return x264Instead("");
    if (encoder == "auto") {
        for (const char* element : kHardwareEncoders)
            if (hasGstElement(element)) return {element, ""};
        return x264Instead("");
    }
    if (hasGstElement(encoder)) return {encoder, ""};
    return x264Instead("encoder " + encoder + " is not on this machine (GStreamer has no element of that name); " +
                       "encoding with x264 instead");
}

PictureSize encodedSize(const H264Settings& settings, PictureSize composite) {
    PictureSize size = settings.size.width > 0 ? settings.size : composite;
    size.width -= size.width % 2;
    size.height -= size.height % 2;
    return size;
}

}  // namespace arcomp
