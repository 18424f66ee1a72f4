#pragma once
// The `encoding` map of a recording or a stream: H.264 settings
// (video/streams/H264Settings.hpp), checked at their lines.
//
//   output:
//     video_file: out/show.mp4
//     encoding: {bitrate_kbps: 6000, keyframe_seconds: 1, size: [1280, 720], encoder: auto}

#include "video/streams/H264Settings.hpp"

namespace arcomp {

class YamlMap;

// Reads `key` of `parent` (absent: the defaults). Whether this machine has
// the encoder is for the station's preflight: reading a config starts no
// GStreamer.
void readEncoding(YamlMap& parent, const char* key, H264Settings& out);

}  // namespace arcomp
