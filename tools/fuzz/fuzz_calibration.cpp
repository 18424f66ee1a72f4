// libFuzzer target: cost-model calibration YAML through readCalibration.
#include "runtime/CalibrationFile.hpp"
#include "runtime/ConfigError.hpp"
#include "tools/fuzz/FuzzInput.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto file = arcomp::fuzz::fuzzInputFile(data, size, "calibration.yaml");
    try {
        arcomp::readCalibration(file);
    } catch (const arcomp::ConfigError&) {
    }
    return 0;
}
