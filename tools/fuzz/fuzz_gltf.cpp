// libFuzzer target: glTF (JSON or GLB, told apart by the magic as the
// loader does) through parseGltf. Relative URIs point into the fuzzer's
// private folder and find nothing there.
#include "graph/io/ModelLoader.hpp"
#include "tools/fuzz/FuzzInput.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return arcomp::fuzz::parseAsFile<arcomp::ModelError>(
        data, size, "model.gltf", [](const std::filesystem::path& file) { arcomp::parseGltf(file); });
}
