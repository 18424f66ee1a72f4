#include "tools/cli/CommandMain.hpp"

#include "graph/core/BadInput.hpp"
#include "runtime/app/ResidentHeap.hpp"

#include <CLI/CLI.hpp>

#include <spdlog/spdlog.h>

#include <algorithm>
#include <iostream>

namespace arcomp {

namespace {

using Actions = std::vector<std::pair<CLI::App*, CommandAction>>;

void addAll(CLI::App& parent, std::vector<Command>& commands, Actions& actions) {
    std::sort(commands.begin(), commands.end(), [](const Command& a, const Command& b) { return a.name < b.name; });
    for (Command& c : commands) {
        CLI::App* sub = parent.add_subcommand(c.name, c.help);
        CommandLine line(*sub);
        actions.emplace_back(sub, c.setup(line));
    }
}

}  // namespace

int runCommandLine(int argc, char** argv, const CommandProgram& program) {
    CLI::App app{program.summary, program.program};
    app.require_subcommand(1);
    if (!program.footer.empty()) app.footer(program.footer);
    std::string logLevel = "warn";
    app.add_option("--log-level", logLevel, "trace, debug, info, warn, error or off")->capture_default_str();

    Actions actions;
    addAll(app, registeredCommands(), actions);
    for (const CommandGroup& g : program.groups) {
        CLI::App* group = app.add_subcommand(g.name, g.help);
        group->require_subcommand(1);
        addAll(*group, *g.commands, actions);
    }

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        if (code != 0 && !program.footer.empty()) std::cerr << program.footer << "\n";
        return code == 0 ? kExitOk : kExitBadInput;
    }
    spdlog::set_level(spdlog::level::from_str(logLevel));
    spdlog::set_pattern("[%H:%M:%S.%e] [%l] %v");
    if (!keepFreedMemoryResident())
        spdlog::info("the C library keeps its own heap policy: frames may page-fault on memory freed by the last one");

    for (auto& [sub, action] : actions) {
        if (!sub->parsed()) continue;
        // "calibrate floor", not "floor": what the user typed.
        const CLI::App* group = sub->get_parent();
        const std::string name = group && group != &app ? group->get_name() + " " + sub->get_name() : sub->get_name();
        try {
            return action();
        } catch (const BadInput& e) {
            std::cerr << program.program << " " << name << ": " << e.what() << "\n";
            return kExitBadInput;
        } catch (const std::exception& e) {
            std::cerr << program.program << " " << name << ": " << e.what() << "\n";
            return kExitFailure;
        }
    }
    return kExitBadInput;
}

}  // namespace arcomp
