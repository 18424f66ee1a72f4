#pragma once
// A trigger as the config gives it (`triggers:`, runtime/config/TriggerConfig.hpp):
// a condition on the visitors and the actions it sets off. A cue from show
// control is one action, done at once (the same TriggerAction).
//
//   Trigger t{.name = "sign",
//             .when = {.event = TriggerEvent::Count, .zone = 0, .atLeast = 1},
//             .actions = {{.kind = ActionKind::Show, .object = "sign"}},
//             .onEnd = {{.kind = ActionKind::Hide, .object = "sign"}}};
//
// Enter and leave are moments: they fire on the frame a person crosses and
// hold for that frame. Dwell, count and near hold as long as they are true
// and fire once when they become true; `onEnd` runs when they stop.

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace arcomp {

enum class TriggerEvent : std::uint8_t {
    Enter,  // a person enters the zone
    Leave,  // a person leaves it
    Dwell,  // someone has been in the zone at least `seconds`
    Count,  // at least `atLeast` people are in the zone
    Near,   // someone stands within `metres` of the object (floor distance; needs a calibrated camera)
};
const char* eventName(TriggerEvent e);  // "enter", "leave", "dwell", "count", "near"

struct TriggerCondition {
    TriggerEvent event = TriggerEvent::Enter;
    int zone = -1;         // enter, leave, dwell, count: index into the config's zones
    std::string object{};  // near
    double seconds = 0.0;
    int atLeast = 1;
    float metres = 1.0f;
    float margin = 0.15f;  // near: out again once beyond metres + margin
};

enum class ActionKind : std::uint8_t {
    Play,      // the object's animation (or `animation`) plays: from its start, or on from a pause
    Pause,     // held where it is
    Stop,      // back to its start, held
    Jump,      // to `seconds` into the clip
    Show,      // drawn again
    Hide,      // not drawn, no shadow, no holdout
    Fade,      // to `opacity` over `seconds`
    Turn,      // about `axis` at `degreesPerSecond` while the trigger holds
    Snapshot,  // the composited frame as a PNG in the folder `file`
    Clip,      // the next `seconds` of composited frames as a video in the folder `file`
    Osc,       // the message `address` with `args` to every OSC target
    Mqtt,      // `payload` to the topic `address` on the broker
};
inline constexpr int kActionKinds = 12;
const char* actionName(ActionKind k);  // the config's word: "play", ..., "mqtt"
std::optional<ActionKind> actionKind(std::string_view word);

// An OSC argument as the config writes it: an integer, a number or a text.
struct OscArgument {
    enum class Type : std::uint8_t { Int, Float, String };
    Type type = Type::Int;
    std::int32_t i = 0;
    float f = 0.0f;
    std::string s{};
};

struct TriggerAction {
    ActionKind kind = ActionKind::Show;
    std::string object{};     // play .. turn
    std::string animation{};  // play: the clip by name or index; empty: the object's own
    double seconds = 0.0;     // jump: where; fade: how long; clip: how long
    float opacity = 1.0f;     // fade: to
    float degreesPerSecond = 0.0f;
    glm::vec3 axis{0.0f, 1.0f, 0.0f};
    std::filesystem::path folder{};  // snapshot, clip
    std::string address{};           // osc: the path; mqtt: the topic
    std::vector<OscArgument> args{};
    std::string payload{};  // mqtt
};

struct Trigger {
    std::string name;
    TriggerCondition when;
    std::vector<TriggerAction> actions;  // when it fires
    std::vector<TriggerAction> onEnd{};  // when a dwell, count or near that fired stops holding
    double cooldownSeconds = 1.0;        // video seconds after a firing before the next
    int line = 0;                        // where it was declared
};

}  // namespace arcomp
