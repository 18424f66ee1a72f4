// libFuzzer target: camera files (camera.calibration, arcomp calibrate) through readCameraFile.
#include "runtime/config/CameraFile.hpp"
#include "runtime/config/ConfigError.hpp"
#include "tools/fuzz/FuzzInput.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return arcomp::fuzz::parseAsFile<arcomp::ConfigError>(
        data, size, "camera.yaml", [](const std::filesystem::path& file) { arcomp::readCameraFile(file); });
}
