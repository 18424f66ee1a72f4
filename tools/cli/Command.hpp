#pragma once
// How subcommands join an executable (arcomp, arcomp-bench). Each command
// lives in its own file, compiled into the executable, and registers itself
// at static-initialisation time:
//
//   static const bool registered = registerCommand({"inspect", "Print a scene's node tree",
//       [](CommandLine& line) {
//           auto path = std::make_shared<std::string>();
//           line.option("scene", *path).required();     // tools/cli/CommandLine.hpp
//           return [path] { return inspect(*path); };   // the exit code
//       }});
//
// `arcomp bake <name>` works the same way through registerBake, and
// `arcomp calibrate <name>` through registerCalibration. The benches are
// arcomp-bench's commands (each prints exactly one JSON object as the last
// line of stdout). tools/cli/CommandMain.hpp runs what was registered.
//
// Exit codes: 0 ok, 1 runtime failure, 2 bad input or usage. Throwing a
// BadInput (graph/core/BadInput.hpp: InputError below, ModelError,
// ConfigError, VideoError, GazeTrackError) from an action gives 2 with its
// message on stderr; any other exception gives 1.

#include "graph/core/BadInput.hpp"

#include "tools/cli/CommandLine.hpp"

#include <functional>
#include <string>
#include <vector>

namespace arcomp {

using CommandAction = std::function<int()>;
using CommandSetup = std::function<CommandAction(CommandLine&)>;

struct Command {
    std::string name;
    std::string help;
    CommandSetup setup;
};

bool registerCommand(Command command);
bool registerBake(Command command);
bool registerCalibration(Command command);
std::vector<Command>& registeredCommands();
std::vector<Command>& registeredBakes();
std::vector<Command>& registeredCalibrations();

// Bad input from the user: a missing file, a value out of range. The
// one-message form is the reason alone (no source, no where), so what() is
// the message as given.
struct InputError : BadInput {
    explicit InputError(std::string reason_) : BadInput("", "", std::move(reason_)) {}
    using BadInput::BadInput;
};

enum ExitCode : int { kExitOk = 0, kExitFailure = 1, kExitBadInput = 2 };

}  // namespace arcomp
