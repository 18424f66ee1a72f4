// arcomp: the station and what an integrator runs on it. Each subcommand
// registers itself (tools/cli/Command.hpp); the benchmarks are arcomp-bench.

#include "tools/cli/CommandMain.hpp"

int main(int argc, char** argv) {
    using namespace arcomp;
    return runCommandLine(
        argc, argv,
        {
            .program = "arcomp",
            .summary = "arcomp: scene-graph runtime for AR compositing stations",
            .footer = "The benchmarks are a program of their own: arcomp-bench <name> (arcomp-bench --help).",
            .groups =
                {
                    {"bake", "Precompute assets: LOD levels, silhouette meshes, voxels", &registeredBakes()},
                    {"calibrate", "Measure the real camera: its lens, and where it stands over the floor",
                     &registeredCalibrations()},
                },
        });
}
