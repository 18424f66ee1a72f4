#pragma once
// What a frame source is doing right now, with the reason a person needs
// when it is not streaming ("/dev/v4l/by-id/usb-cam: ENODEV while streaming").
//
//   SourceState s = source.state();
//   if (s.status == SourceStatus::Disconnected) spdlog::warn("{}", s.reason);

#include <string>
#include <string_view>

namespace arcomp {

enum class SourceStatus {
    Opening,       // not yet produced a frame
    Streaming,     // frames arriving
    Stalled,       // open, but no frame within a few frame periods
    Disconnected,  // device gone or not present; the source keeps trying to get it back
    Ended,         // a file reached its end (and does not loop)
    Error,         // unusable (damaged file, unsupported format); reason says what and where
};

struct SourceState {
    SourceStatus status = SourceStatus::Opening;
    std::string reason;
};

std::string_view sourceStatusName(SourceStatus status);

// True when a station should show its fallback instead of this source.
inline bool isLost(SourceStatus status) {
    return status == SourceStatus::Disconnected || status == SourceStatus::Ended || status == SourceStatus::Error;
}

}  // namespace arcomp
