#include "video/pixels/PixelFormat.hpp"

#include <linux/videodev2.h>

#include <algorithm>
#include <cctype>

namespace arcomp {

std::string_view pixelFormatName(PixelFormat format) {
    switch (format) {
    case PixelFormat::Bgr: return "BGR";
    case PixelFormat::Yuyv: return "YUYV";
    case PixelFormat::Nv12: return "NV12";
    case PixelFormat::Mjpeg: return "MJPEG";
    case PixelFormat::Encoded: return "encoded";
    }
    return "unknown";
}

std::optional<PixelFormat> pixelFormatFromName(std::string_view name) {
    std::string lower(name);
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
    if (lower == "bgr") return PixelFormat::Bgr;
    if (lower == "yuyv") return PixelFormat::Yuyv;
    if (lower == "nv12") return PixelFormat::Nv12;
    if (lower == "mjpeg" || lower == "mjpg") return PixelFormat::Mjpeg;
    return std::nullopt;
}

std::optional<std::uint32_t> pixelFormatFourcc(PixelFormat format) {
    switch (format) {
    case PixelFormat::Yuyv: return V4L2_PIX_FMT_YUYV;
    case PixelFormat::Nv12: return V4L2_PIX_FMT_NV12;
    case PixelFormat::Mjpeg: return V4L2_PIX_FMT_MJPEG;
    default: return std::nullopt;
    }
}

std::optional<PixelFormat> pixelFormatFromFourcc(std::uint32_t fourcc) {
    switch (fourcc) {
    case V4L2_PIX_FMT_YUYV: return PixelFormat::Yuyv;
    case V4L2_PIX_FMT_NV12: return PixelFormat::Nv12;
    case V4L2_PIX_FMT_MJPEG:
    case V4L2_PIX_FMT_JPEG: return PixelFormat::Mjpeg;
    default: return std::nullopt;
    }
}

std::string fourccString(std::uint32_t fourcc) {
    std::string s;
    for (int i = 0; i < 4; ++i) {
        const char c = static_cast<char>((fourcc >> (8 * i)) & 0xff);
        s += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
    }
    return s;
}

}  // namespace arcomp
