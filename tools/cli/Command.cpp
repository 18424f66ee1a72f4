#include "tools/cli/Command.hpp"

namespace arcomp {

std::vector<Command>& registeredCommands() {
    static std::vector<Command> commands;
    return commands;
}

std::vector<Command>& registeredBakes() {
    static std::vector<Command> bakes;
    return bakes;
}

std::vector<Command>& registeredCalibrations() {
    static std::vector<Command> calibrations;
    return calibrations;
}

bool registerCalibration(Command command) {
    registeredCalibrations().push_back(std::move(command));
    return true;
}

bool registerBake(Command command) {
    registeredBakes().push_back(std::move(command));
    return true;
}

bool registerCommand(Command command) {
    registeredCommands().push_back(std::move(command));
    return true;
}

}  // namespace arcomp
