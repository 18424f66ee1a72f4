#pragma once
// Where a station's log goes: stderr always, and a size-rotated file when
// the config names one, so a kiosk that runs for months keeps a bounded
// history an operator can collect.
//
//   configureLogging({.level = "info", .file = "/var/log/arcomp/station.log"});

#include "runtime/config/OperatorConfig.hpp"

namespace arcomp {

// Replaces the default logger. Throws std::runtime_error naming the file
// when the log file cannot be opened (the caller decides whether to go on
// with stderr alone).
void configureLogging(const LogSettings& settings);

}  // namespace arcomp
