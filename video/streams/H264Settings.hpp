#pragma once
// How a stream or a recording is encoded: H.264 at a bitrate, a keyframe
// every so often, at the composite's size or smaller. x264 by default; a
// hardware encoder (VA-API, V4L2 M2M) when the config names one and the
// machine has it, else x264 with a warning, so that one config serves a
// kiosk PC and a board alike.
//
//   H264Settings s{.bitrateKbps = 6000, .size = {1280, 720}};
//   const EncoderChoice e = chooseH264Encoder(s.encoder);  // e.element == "x264enc"

#include <string>

namespace arcomp {

struct PictureSize {
    int width = 0;  // 0: the composite's
    int height = 0;
};

struct H264Settings {
    int bitrateKbps = 4000;
    double keyframeSeconds = 2.0;  // a receiver joining waits at most this long for a picture
    PictureSize size{};            // even; never larger than the composite
    // "x264", "auto" (the first hardware encoder this machine has, else
    // x264) or a GStreamer element name such as "vaapih264enc".
    std::string encoder = "x264";
    // Streams: no lookahead or B-frames, a frame leaves as soon as it is
    // encoded. Recordings trade that delay for fewer bits.
    bool lowLatency = true;
};

struct EncoderChoice {
    std::string element;  // empty: none (not even x264enc); `warning` says why
    std::string warning;  // set when the one asked for is missing
};

// Which element encodes for `encoder` on this machine.
EncoderChoice chooseH264Encoder(const std::string& encoder);

// The picture an encoder gets for a composite of `composite`: the size
// asked for, or the composite's; rounded down to even, as 4:2:0 needs.
PictureSize encodedSize(const H264Settings& settings, PictureSize composite);

}  // namespace arcomp
