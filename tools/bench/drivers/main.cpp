// arcomp-bench: the benchmarks, apart from the station's binary. Each bench
// registers itself as a command (tools/cli/Command.hpp), runs against its
// peer in the same run and prints one JSON object as its last line.

#include "tools/cli/CommandMain.hpp"

int main(int argc, char** argv) {
    using namespace arcomp;
    return runCommandLine(
        argc, argv,
        {
            .program = "arcomp-bench",
            .summary = "arcomp-bench: benchmarks; each prints one JSON object as its last line",
            .footer = "Each bench drives the station binary, arcomp, found beside this one or on PATH.",
            .groups = {},
        });
}
