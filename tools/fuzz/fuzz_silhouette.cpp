// libFuzzer target: baked silhouette files through decodeSilhouetteMesh.
#include "graph/io/SilhouetteFile.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        arcomp::decodeSilhouetteMesh(std::span(reinterpret_cast<const std::byte*>(data), size), "fuzz.sil");
    } catch (const arcomp::ModelError&) {}
    return 0;
}
