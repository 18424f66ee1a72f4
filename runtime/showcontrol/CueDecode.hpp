#pragma once
// Cues off the wire (runtime/triggers/Cue.hpp), decoded without trusting a
// byte: an OSC message through liblo's checked deserialiser, an MQTT
// payload as JSON. What does not decode is an error that says what was
// wrong and what was expected, never a crash; the callers count it.
//
//   CueDecoded d = decodeOscCue(datagram);              // /arcomp/cue/play ,ss dino roar
//   CueDecoded e = decodeJsonCue(R"({"cue": "hide", "object": "sign"})");

#include "runtime/triggers/Cue.hpp"

#include <cstdint>
#include <span>
#include <string_view>

namespace arcomp {

inline constexpr std::string_view kOscCuePrefix = "/arcomp/cue/";

CueDecoded decodeOscCue(std::span<const std::uint8_t> datagram);
CueDecoded decodeJsonCue(std::string_view payload);

}  // namespace arcomp
