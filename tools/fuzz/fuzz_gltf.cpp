// libFuzzer target: glTF (JSON or GLB, told apart by the magic as the
// loader does) through parseGltf. Relative URIs point into the fuzzer's
// private folder and find nothing there.
#include "graph/ModelLoader.hpp"
#include "tools/fuzz/FuzzInput.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto file = arcomp::fuzz::fuzzInputFile(data, size, "model.gltf");
    try {
        arcomp::parseGltf(file);
    } catch (const arcomp::ModelError&) {
    }
    return 0;
}
