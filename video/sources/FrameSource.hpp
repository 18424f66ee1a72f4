#pragma once
// What the render loop sees of a camera, file or pattern: the newest frame,
// never a late one, without ever blocking.
//
//   std::unique_ptr<FrameSource> cam = openSource(spec);   // already open
//   if (std::optional<Frame> f = cam->newest()) show(*f);  // new frame, or nothing new
//   if (isLost(cam->state().status)) ...                   // see FallbackSource
//
// newest() returns each frame at most once; frames the consumer was too
// slow to take are counted by drops(). Implementations capture on their own
// thread (CaptureThread) or wrap other sources (FallbackSource).

#include "video/pixels/Frame.hpp"
#include "video/sources/SourceStatus.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace arcomp {

class FrameSource {
public:
    virtual ~FrameSource() = default;
    // Starts capturing. Never throws for a missing device or file: that
    // shows up in state().
    virtual void open() = 0;
    virtual std::optional<Frame> newest() = 0;
    virtual SourceState state() const = 0;
    virtual std::uint64_t drops() const = 0;
    // Stops capturing and joins the capture thread; safe to call twice.
    virtual void close() = 0;
    virtual std::string name() const = 0;
};

}  // namespace arcomp
