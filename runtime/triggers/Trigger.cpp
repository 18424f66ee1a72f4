#include "runtime/triggers/Trigger.hpp"

#include <array>

namespace arcomp {
namespace {

// In ActionKind's order.
constexpr std::array<const char*, kActionKinds> kActionWords{"play", "pause", "stop",     "jump", "show", "hide",
                                                             "fade", "turn",  "snapshot", "clip", "osc",  "mqtt"};

}  // namespace

const char* eventName(TriggerEvent e) {
    switch (e) {
    case TriggerEvent::Enter: return "enter";
    case TriggerEvent::Leave: return "leave";
    case TriggerEvent::Dwell: return "dwell";
    case TriggerEvent::Count: return "count";
    case TriggerEvent::Near: return "near";
    }
    return "?";
}

const char* actionName(ActionKind k) { return kActionWords.at(static_cast<std::size_t>(k)); }

std::optional<ActionKind> actionKind(std::string_view word) {
    for (std::size_t k = 0; k < kActionWords.size(); ++k)
        if (word == kActionWords[k]) return static_cast<ActionKind>(k);
    return std::nullopt;
}

}  // namespace arcomp
