// libFuzzer target: station config YAML text through loadStationConfig.
#include "runtime/config/ConfigError.hpp"
#include "runtime/config/StationConfig.hpp"
#include "tools/fuzz/FuzzInput.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return arcomp::fuzz::parseAsFile<arcomp::ConfigError>(
        data, size, "station.yaml", [](const std::filesystem::path& file) { arcomp::loadStationConfig(file); });
}
