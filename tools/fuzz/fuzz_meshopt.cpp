// libFuzzer target: an EXT_meshopt_compression stream through parseGltf.
// The input is a header (mode, filter, byteStride / 4, count as a
// little-endian u16) and the stream, which becomes the GLB's BIN chunk; the
// decoded view is a fallback buffer whose POSITION a triangle list reads,
// so decoded bytes also go through the accessor checks. The seeds
// (make_seeds) are meshoptimizer's own encodings with true headers.
#include "graph/io/ModelLoader.hpp"
#include "tools/fuzz/FuzzInput.hpp"
#include "tools/fuzz/GlbAround.hpp"

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 5) return 0;
    static const char* const kModes[] = {"ATTRIBUTES", "TRIANGLES", "INDICES", "BOGUS"};
    static const char* const kFilters[] = {"NONE", "OCTAHEDRAL", "QUATERNION", "EXPONENTIAL"};
    const std::string mode = kModes[data[0] % 4], filter = kFilters[data[1] % 4];
    const std::size_t stride = std::size_t(data[2] % 65) * 4, count = data[3] | std::size_t(data[4]) << 8;
    const std::string length = std::to_string(size - 5), decoded = std::to_string(stride * count);
    const std::string json = R"({"asset": {"version": "2.0"},
      "extensionsUsed": ["EXT_meshopt_compression"], "extensionsRequired": ["EXT_meshopt_compression"],
      "buffers": [{"byteLength": )" +
                             length + R"(},
                  {"byteLength": )" +
                             decoded + R"(, "extensions": {"EXT_meshopt_compression": {"fallback": true}}}],
      "bufferViews": [{"buffer": 1, "byteLength": )" +
                             decoded + R"(, "byteStride": )" + std::to_string(stride) + R"(,
        "extensions": {"EXT_meshopt_compression": {"buffer": 0, "byteLength": )" +
                             length + R"(, "byteStride": )" + std::to_string(stride) + R"(, "count": )" +
                             std::to_string(count) + R"(, "mode": ")" + mode + R"(", "filter": ")" + filter + R"("}}}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" +
                             std::to_string(count) + R"(, "type": "VEC3"}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
      "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]})";
    const std::string glb = arcomp::fuzz::glbAround(json, data + 5, size - 5);
    return arcomp::fuzz::parseAsFile<arcomp::ModelError>(
        reinterpret_cast<const std::uint8_t*>(glb.data()), glb.size(), "model.glb",
        [](const std::filesystem::path& file) { arcomp::parseGltf(file); });
}
