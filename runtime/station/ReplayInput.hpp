#pragma once
// The input of a replay: a config's video source opened for frame-exact,
// unpaced pulling. A file that is missing or unreadable falls back to the
// generated test pattern when the config names a fallback, with a warning
// saying so; otherwise it throws VideoError (bad input: arcomp exits 2).
//
//   std::vector<std::string> warnings;
//   StationInput in = openReplayInput(*cfg.compositing.video, warnings);

#include "runtime/station/Station.hpp"
#include "video/sources/SourceSpec.hpp"

namespace arcomp {

StationInput openReplayInput(const SourceSpec& spec, std::vector<std::string>& warnings);

}  // namespace arcomp
