#include "video/sources/SourceStatus.hpp"

namespace arcomp {

std::string_view sourceStatusName(SourceStatus status) {
    switch (status) {
    case SourceStatus::Opening: return "opening";
    case SourceStatus::Streaming: return "streaming";
    case SourceStatus::Stalled: return "stalled";
    case SourceStatus::Disconnected: return "disconnected";
    case SourceStatus::Ended: return "ended";
    case SourceStatus::Error: return "error";
    }
    return "unknown";
}

}  // namespace arcomp
