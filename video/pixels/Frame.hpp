#pragma once
// One video frame as a source hands it over: BGR pixels (as OpenCV decodes;
// the renderer swizzles to RGB on upload), when it was captured, its place in
// the source's sequence, and the layout it arrived in.
//
//   if (std::optional<Frame> f = source.newest())
//       upload(f->image);   // CV_8UC3, f->image.cols x f->image.rows

#include "video/pixels/PixelFormat.hpp"

#include <opencv2/core/mat.hpp>

#include <chrono>
#include <cstdint>

namespace arcomp {

struct Frame {
    cv::Mat image;  // CV_8UC3, BGR
    // The frame's time on its source's own timeline: the driver timestamp
    // for cameras, time since the first frame for files and patterns. Replay
    // uses this; it is deterministic for files.
    std::chrono::nanoseconds timestamp{0};
    // When the frame was captured on this machine's steady clock; latency is
    // measured from here to the moment the consumer takes the frame.
    std::chrono::steady_clock::time_point captured{};
    std::uint64_t sequence = 0;  // 0, 1, 2, ... as produced; gaps mean drops or skipped damage
    PixelFormat format = PixelFormat::Bgr;
};

}  // namespace arcomp
