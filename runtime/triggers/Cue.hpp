#pragma once
// A cue from show control: what an OSC message (/arcomp/cue/<verb> with
// string arguments) or an MQTT message ({"cue": "<verb>", ...}) asks the
// station to do now. The same words on both:
//
//   play OBJECT [ANIMATION]   its animation plays (ANIMATION: another of its clips)
//   pause OBJECT | stop OBJECT
//   show OBJECT | hide OBJECT
//   snapshot                  the composited frame, into show_control.cues.snapshot_folder
//   reload                    the config, as SIGHUP does
//
//   CueDecoded d = cueFromWords("play", {"dino", "roar"});
//   if (d.cue) station.cue(*d.cue); else log(d.error);

#include "runtime/triggers/Trigger.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace arcomp {

struct Cue {
    enum class Kind : std::uint8_t { Action, Reload };
    Kind kind = Kind::Action;
    TriggerAction action{};  // Kind::Action: play, pause, stop, show, hide (with object) or snapshot
};

struct CueDecoded {
    std::optional<Cue> cue;
    std::string error{};  // why there is none: what was wrong and what was expected
};

// The verb and its arguments, checked: a known verb, its number of arguments.
CueDecoded cueFromWords(std::string_view verb, const std::vector<std::string>& args);

}  // namespace arcomp
