// libFuzzer target: Wavefront OBJ text through parseObj.
#include "graph/ModelLoader.hpp"
#include "tools/fuzz/FuzzInput.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto file = arcomp::fuzz::fuzzInputFile(data, size, "model.obj");
    try {
        arcomp::parseObj(file);
    } catch (const arcomp::ModelError&) {
    }
    return 0;
}
