#pragma once
// Running another program from a benchmark: a peer to compare against (the
// three.js renderer, GStreamer) or this binary with other arguments. The
// command goes through /bin/sh, so quote what comes from outside.
//
//   if (onPath("gst-launch-1.0")) {
//       const ShellResult r = runShellCommand("gst-launch-1.0 -q " + shellQuote(pipeline));
//       if (r.status != 0) std::cerr << r.output;
//   }

#include <string>

namespace arcomp {

struct ShellResult {
    int status = -1;     // the exit status; -1 when the program did not exit normally
    std::string output;  // stdout and stderr together
};

// Runs `command` with /bin/sh and waits for it; throws std::runtime_error
// when no shell could be started.
ShellResult runShellCommand(const std::string& command);
// Whether an executable `program` is in one of the folders on PATH.
bool onPath(const std::string& program);
// `text` as one shell word.
std::string shellQuote(const std::string& text);
// The station binary the benches drive (`arcomp render`, `arcomp calibrate`):
// the `arcomp` beside this executable, as the build and the package place
// them, else the one on PATH. Throws std::runtime_error when there is none.
std::string stationBinary();

}  // namespace arcomp
