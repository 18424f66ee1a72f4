// arcomp check <station.yaml>: validates an installation without running
// it, for integrators before they ship a config to a kiosk. Every config
// error is listed with file:line:column; every model is loaded, so an asset
// that the station would skip at run time fails the check here.

#include "runtime/config/StationConfig.hpp"
#include "runtime/station/SceneFile.hpp"
#include "runtime/station/Station.hpp"
#include "tools/cli/Command.hpp"

#include <iostream>
#include <memory>

namespace arcomp {
namespace {

int check(const std::string& file) {
    const StationConfig cfg = loadStationConfig(file);  // ConfigError: exit 2 with every problem
    try {
        Station::preflight(cfg);  // calibration, gaze track, matte settings
    } catch (const std::exception& e) {
        throw InputError(file, "", e.what());
    }
    // A listening stream's port, free now: a running station holds its own,
    // so only the check, not a reload, asks.
    for (const StreamConfig& s : cfg.compositing.output.streams)
        if (const std::string why = listenProblem(s.spec); !why.empty())
            throw InputError(s.at, "output.streams " + s.spec.name + ".url", why);
    World world;  // everything a station would build, voxel files included
    std::vector<std::string> problems;
    buildScene(cfg, world, problems);
    for (const std::string& p : problems) std::cerr << file << ": " << p << "\n";
    if (!problems.empty()) {
        std::cerr << file << ": " << problems.size() << " problem(s); the station would run without those objects\n";
        return kExitBadInput;
    }
    std::cout << file << ": ok (" << cfg.objects.size() << " objects, " << world.scene.nodeCount() << " nodes)\n";
    return kExitOk;
}

const bool registered = registerCommand(
    {"check", "Validate a station config and load its assets without running it", [](CommandLine& line) {
         auto file = std::make_shared<std::string>();
         line.option("config", *file, "Station config (.yaml)").required();
         return [file] { return check(*file); };
     }});

}  // namespace
}  // namespace arcomp
