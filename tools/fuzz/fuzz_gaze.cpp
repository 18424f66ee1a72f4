// libFuzzer target: recorded gaze track CSV through parseGazeTrackCsv.
#include "runtime/station/GazeSource.hpp"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        arcomp::parseGazeTrackCsv(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.csv");
    } catch (const arcomp::GazeTrackError&) {}
    return 0;
}
