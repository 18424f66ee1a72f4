// libFuzzer target: baked LOD files through parseLodFile.
#include "graph/io/LodFile.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        arcomp::parseLodFile(std::span<const unsigned char>(data, size), "fuzz.lod");
    } catch (const arcomp::ModelError&) {}
    return 0;
}
