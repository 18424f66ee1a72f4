// arcomp: the station and its tools. Each subcommand registers itself (see
// Command.hpp); this file only parses the command line and maps failures to
// exit codes.

#include "graph/core/BadInput.hpp"
#include "runtime/app/ResidentHeap.hpp"
#include "tools/arcomp/Command.hpp"

#include <CLI/CLI.hpp>

#include <spdlog/spdlog.h>

#include <algorithm>
#include <iostream>
#include <tuple>

using namespace arcomp;

namespace {

void addAll(CLI::App& parent, std::vector<Command>& commands, std::vector<std::pair<CLI::App*, CommandAction>>& actions) {
    std::sort(commands.begin(), commands.end(), [](const Command& a, const Command& b) { return a.name < b.name; });
    for (Command& c : commands) {
        CLI::App* sub = parent.add_subcommand(c.name, c.help);
        CommandLine line(*sub);
        actions.emplace_back(sub, c.setup(line));
    }
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"arcomp: scene-graph runtime for AR compositing stations"};
    app.require_subcommand(1);
    std::string logLevel = "warn";
    app.add_option("--log-level", logLevel, "trace, debug, info, warn, error or off")->capture_default_str();

    std::vector<std::pair<CLI::App*, CommandAction>> actions;
    addAll(app, registeredCommands(), actions);
    const std::tuple<const char*, const char*, std::vector<Command>&> groups[] = {
        {"bench", "Benchmarks; each prints one JSON object as its last line", registeredBenches()},
        {"bake", "Precompute assets: LOD levels, silhouette meshes, voxels", registeredBakes()},
        {"calibrate", "Measure the real camera: its lens, and where it stands over the floor", registeredCalibrations()},
    };
    for (const auto& [name, help, commands] : groups) {
        CLI::App* group = app.add_subcommand(name, help);
        group->require_subcommand(1);
        addAll(*group, commands, actions);
    }

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
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
            std::cerr << "arcomp " << name << ": " << e.what() << "\n";
            return kExitBadInput;
        } catch (const std::exception& e) {
            std::cerr << "arcomp " << name << ": " << e.what() << "\n";
            return kExitFailure;
        }
    }
    return kExitBadInput;
}
