#pragma once
// The blocking side of a source: grab() waits for the next frame (or for a
// few frame periods at most) and returns it, or says why there is none.
// Cameras, files and patterns implement this; CaptureThread runs one on its
// own thread to make a non-blocking FrameSource, and replay calls grab()
// directly for deterministic, frame-exact stepping.
//
//   TestPatternSource pattern({.width = 640, .height = 480, .fps = 30});
//   GrabResult r = pattern.grab();   // r.frame->sequence == 0

#include "video/pixels/Frame.hpp"
#include "video/sources/SourceStatus.hpp"

#include <optional>
#include <string>

namespace arcomp {

struct GrabResult {
    std::optional<Frame> frame;  // set when status is Streaming
    SourceState state;           // Streaming with a frame, or why there is none
};

class FrameGrabber {
public:
    virtual ~FrameGrabber() = default;
    // Returns within a few frame periods even when the device is silent,
    // so that the capture thread can notice close().
    virtual GrabResult grab() = 0;
    // A short name for logs: the path, device or "pattern 640x480@30".
    virtual std::string name() const = 0;
};

}  // namespace arcomp
