// libFuzzer target: Wavefront OBJ text through parseObj.
#include "graph/io/ModelLoader.hpp"
#include "tools/fuzz/FuzzInput.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return arcomp::fuzz::parseAsFile<arcomp::ModelError>(
        data, size, "model.obj", [](const std::filesystem::path& file) { arcomp::parseObj(file); });
}
