#pragma once
// An executable's main() over the registered commands (tools/cli/Command.hpp):
// parses the command line, sets the log level, runs the one command given and
// maps what it throws to an exit code, with "program command: reason" on
// stderr.
//
//   int main(int argc, char** argv) {
//       return arcomp::runCommandLine(argc, argv, {
//           .program = "arcomp-bench",
//           .summary = "arcomp-bench: benchmarks, each against its peer",
//           .footer = "arcomp --help lists the station's own commands.",
//           .groups = {},
//       });
//   }

#include "tools/cli/Command.hpp"

#include <string>
#include <vector>

namespace arcomp {

// A subcommand that holds commands of its own: `arcomp bake lod`.
struct CommandGroup {
    std::string name;
    std::string help;
    std::vector<Command>* commands = nullptr;
};

struct CommandProgram {
    std::string program;  // names the program in error messages
    std::string summary;  // --help's first line
    std::string footer;   // --help's last, and after a command line it cannot parse
    std::vector<CommandGroup> groups;
};

// The exit code (ExitCode); registeredCommands() are the top-level commands.
int runCommandLine(int argc, char** argv, const CommandProgram& program);

}  // namespace arcomp
