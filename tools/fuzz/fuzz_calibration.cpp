// libFuzzer target: cost-model calibration YAML through readCalibration.
#include "runtime/config/CalibrationFile.hpp"
#include "runtime/config/ConfigError.hpp"
#include "tools/fuzz/FuzzInput.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return arcomp::fuzz::parseAsFile<arcomp::ConfigError>(
        data, size, "calibration.yaml", [](const std::filesystem::path& file) { arcomp::readCalibration(file); });
}
