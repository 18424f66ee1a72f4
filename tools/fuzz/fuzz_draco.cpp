// libFuzzer target: a KHR_draco_mesh_compression stream through parseGltf.
// The input is the points and indices its accessors declare (two
// little-endian u32), then the Draco stream, which becomes the GLB's BIN
// chunk; the seeds (make_seeds) are real streams with their true counts.
#include "graph/io/ModelLoader.hpp"
#include "tools/fuzz/FuzzInput.hpp"
#include "tools/fuzz/GlbAround.hpp"

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 8) return 0;
    const auto u32 = [data](std::size_t at) {
        return data[at] | data[at + 1] << 8 | data[at + 2] << 16 | std::uint32_t(data[at + 3]) << 24;
    };
    const std::string points = std::to_string(u32(0)), indices = std::to_string(u32(4));
    const std::string json = R"({"asset": {"version": "2.0"},
      "extensionsUsed": ["KHR_draco_mesh_compression"], "extensionsRequired": ["KHR_draco_mesh_compression"],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3,
        "extensions": {"KHR_draco_mesh_compression": {"bufferView": 0,
          "attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}}}}]}],
      "accessors": [{"componentType": 5126, "count": )" +
                             points + R"(, "type": "VEC3"},
                    {"componentType": 5126, "count": )" +
                             points + R"(, "type": "VEC3"},
                    {"componentType": 5126, "count": )" +
                             points + R"(, "type": "VEC2"},
                    {"componentType": 5125, "count": )" +
                             indices + R"(, "type": "SCALAR"}],
      "bufferViews": [{"buffer": 0, "byteLength": )" +
                             std::to_string(size - 8) + R"(}],
      "buffers": [{"byteLength": )" +
                             std::to_string(size - 8) + R"(}],
      "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]})";
    const std::string glb = arcomp::fuzz::glbAround(json, data + 8, size - 8);
    return arcomp::fuzz::parseAsFile<arcomp::ModelError>(
        reinterpret_cast<const std::uint8_t*>(glb.data()), glb.size(), "model.glb",
        [](const std::filesystem::path& file) { arcomp::parseGltf(file); });
}
