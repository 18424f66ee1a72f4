#pragma once
// Everything needed to open a video input, as plain data. The station's
// config loader fills it from YAML; tests and tools fill it directly.
//
//   SourceSpec spec{.kind = SourceKind::V4l2, .path = "/dev/v4l/by-id/usb-cam-video-index0",
//                   .fallback = {FallbackKind::Pattern}};
//   std::unique_ptr<FrameSource> cam = openSource(spec);   // open and capturing

#include "video/pixels/PixelFormat.hpp"
#include "video/sources/FileSource.hpp"

#include <string>
#include <vector>

namespace arcomp {

enum class SourceKind { File, V4l2, Libcamera, Pattern };

// What to show while the primary source is missing or lost.
enum class FallbackKind { None, File, Image, LastGoodFrame, Pattern };

struct FallbackSpec {
    FallbackKind kind = FallbackKind::None;
    std::string path;  // the file or still image
};

struct SourceSpec {
    SourceKind kind = SourceKind::Pattern;
    std::string path;  // file path, device (prefer /dev/v4l/by-id/...), or libcamera id ("" = first)
    int width = 1280;  // cameras and pattern; files keep their own size
    int height = 720;
    double fps = 30.0;                 // cameras and pattern; files keep their own rate
    std::vector<PixelFormat> formats;  // camera preference, first wins; empty = the source's default
    bool loop = false;                 // files
    bool paced = true;                 // files and pattern: real time; false = as fast as possible
    OnDamage onDamage = OnDamage::Stop;
    FallbackSpec fallback;
};

}  // namespace arcomp
