#pragma once
// The pixel layouts a source can deliver before conversion to BGR. Cameras
// negotiate one of these; files report the codec they were decoded from.
//
//   PixelFormat f = pixelFormatFromName("mjpeg");   // PixelFormat::Mjpeg
//   pixelFormatName(f);                             // "MJPEG"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace arcomp {

enum class PixelFormat : std::uint8_t {
    Bgr,      // already 8-bit BGR (test pattern, still images)
    Yuyv,     // packed 4:2:2, Y0 U Y1 V
    Nv12,     // planar Y, then interleaved UV at half resolution
    Mjpeg,    // one JPEG per frame
    Encoded,  // a compressed file stream decoded by FFmpeg (codec in the source's description)
};

std::string_view pixelFormatName(PixelFormat format);
// Accepts "yuyv", "YUYV", "mjpeg", "nv12", "bgr"; nullopt otherwise.
std::optional<PixelFormat> pixelFormatFromName(std::string_view name);
// V4L2/libcamera fourcc of a camera format; nullopt for Bgr and Encoded.
std::optional<std::uint32_t> pixelFormatFourcc(PixelFormat format);
std::optional<PixelFormat> pixelFormatFromFourcc(std::uint32_t fourcc);
// "YUYV", "MJPG", "H264": printable four characters of a fourcc.
std::string fourccString(std::uint32_t fourcc);

}  // namespace arcomp
