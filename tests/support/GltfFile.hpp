#pragma once
// glTF text for tests: one embedded base64 buffer holding a triangle mesh
// (accessors 0 and 1), then whatever accessors a test adds, each in its own
// buffer view. Tests set the nodes, animations and skins as JSON text.
//
//   GltfFile f;
//   const int times = f.add({0, 1}, "SCALAR");
//   const int moves = f.add({0, 0, 0, 1, 0, 0}, "VEC3");
//   f.animations = R"([{"samplers": [...], "channels": [...]}])";
//   dir.write("model.gltf", f.json());

#include "graph/io/Base64.hpp"
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace arcomp::test {

struct GltfFile {
    std::vector<unsigned char> bin;
    std::vector<std::string> views, accessors;
    std::string nodes = R"([{"name": "spinner", "mesh": 0}])";
    std::string animations = "[]";
    std::string skins;
    // More of the mesh's attributes, as JSON members after POSITION: `, "JOINTS_0": 2`.
    std::string attributes;

    GltfFile() {
        add({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
        const std::uint16_t indices[3] = {0, 1, 2};
        addBytes(indices, sizeof indices, 3, "SCALAR", 5123);
    }

    int add(const std::vector<float>& values, const char* type, std::size_t components = 0) {
        const std::size_t width = components ? components : std::string(type) == "SCALAR" ? 1 : std::string(type) == "VEC3" ? 3
                                                          : std::string(type) == "VEC4"     ? 4
                                                                                            : 16;
        return addBytes(values.data(), values.size() * sizeof(float), values.size() / width, type, 5126);
    }

    int addBytes(const void* data, std::size_t size, std::size_t count, const char* type, int componentType,
                 bool normalized = false) {
        const std::size_t offset = bin.size();
        bin.resize(offset + ((size + 3) & ~std::size_t{3}), 0);
        std::memcpy(bin.data() + offset, data, size);
        views.push_back(R"({"buffer": 0, "byteOffset": )" + std::to_string(offset) + R"(, "byteLength": )" +
                        std::to_string(size) + "}");
        accessors.push_back(R"({"bufferView": )" + std::to_string(views.size() - 1) + R"(, "componentType": )" +
                            std::to_string(componentType) + R"(, "count": )" + std::to_string(count) +
                            R"(, "type": ")" + type + "\"" + (normalized ? R"(, "normalized": true)" : "") + "}");
        return static_cast<int>(accessors.size() - 1);
    }

    std::string json() const {
        auto list = [](const std::vector<std::string>& items) {
            std::string out = "[";
            for (std::size_t i = 0; i < items.size(); ++i) out += (i ? ", " : "") + items[i];
            return out + "]";
        };
        return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": )" + nodes +
               R"(, "meshes": [{"primitives": [{"attributes": {"POSITION": 0)" + attributes +
               R"(}, "indices": 1}]}], "animations": )" +
               animations + (skins.empty() ? "" : R"(, "skins": )" + skins) + R"(, "accessors": )" + list(accessors) +
               R"(, "bufferViews": )" + list(views) + R"(, "buffers": [{"byteLength": )" + std::to_string(bin.size()) +
               R"(, "uri": "data:application/octet-stream;base64,)" + base64(bin) + "\"}]}";
    }
};

} // namespace arcomp::test
