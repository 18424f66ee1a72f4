// libFuzzer target: station config YAML text through loadStationConfig.
#include "runtime/ConfigError.hpp"
#include "runtime/StationConfig.hpp"
#include "tools/fuzz/FuzzInput.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto file = arcomp::fuzz::fuzzInputFile(data, size, "station.yaml");
    try {
        arcomp::loadStationConfig(file);
    } catch (const arcomp::ConfigError&) {
    }
    return 0;
}
