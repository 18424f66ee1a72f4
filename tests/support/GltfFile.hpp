#pragma once
// glTF text for tests: a triangle mesh (accessors 0 and 1), then whatever
// accessors a test adds. Tests set the nodes, animations and skins as JSON
// text. Written by graph/io/GltfWriter.
//
//   GltfFile f;
//   const int times = f.add({0, 1}, "SCALAR");
//   const int moves = f.add({0, 0, 0, 1, 0, 0}, "VEC3");
//   f.animations = R"([{"samplers": [...], "channels": [...]}])";
//   dir.write("model.gltf", f.json());

#include "graph/io/GltfWriter.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace arcomp::test {

struct GltfFile {
    GltfWriter writer;
    std::string nodes = R"([{"name": "spinner", "mesh": 0}])";
    std::string animations = "[]";
    std::string skins = "[]";
    // More of the mesh's attributes, as JSON members after POSITION: `, "JOINTS_0": 2`.
    std::string attributes;

    GltfFile() {
        add({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
        const std::uint16_t indices[3] = {0, 1, 2};
        addBytes(indices, 3, "SCALAR", GltfWriter::kUnsignedShort);
    }

    // Floats, as many elements of `type` as `values` holds.
    int add(const std::vector<float>& values, const char* type) {
        const std::size_t width = GltfWriter::components(type);
        return writer.accessor(values.data(), values.size() / width, type, GltfWriter::kFloat);
    }

    // `count` elements of `type` of `componentType` (GltfWriter::kUnsignedByte, ...).
    int addBytes(const void* data, std::size_t count, const char* type, int componentType, bool normalized = false) {
        return writer.accessor(data, count, type, componentType, {.normalized = normalized});
    }

    std::string json() const {
        GltfWriter w = writer;
        w.nodes = GltfWriter::Json::parse(nodes);
        w.animations = GltfWriter::Json::parse(animations);
        w.skins = GltfWriter::Json::parse(skins);
        GltfWriter::add(w.meshes,
                        R"({"primitives": [{"attributes": {"POSITION": 0)" + attributes + R"(}, "indices": 1}]})");
        w.sceneNodes = {0};
        return w.text();
    }
};

// A triangle that slides from x = -1 to x = 1 over the first second
// ("slide") and a second clip that only scales it ("grow").
inline std::string slidingTriangle() {
    GltfFile f;
    f.nodes = R"([{"name": "slider", "mesh": 0, "translation": [-1, 0, 0]}])";
    const int times = f.add({0, 1}, "SCALAR");
    const int slide = f.add({-1, 0, 0, 1, 0, 0}, "VEC3");
    const int grow = f.add({1, 1, 1, 2, 2, 2}, "VEC3");
    const auto channel = [&](int output, const char* path) {
        return R"({"samplers": [{"input": )" + std::to_string(times) + R"(, "output": )" + std::to_string(output) +
               R"(}], "channels": [{"sampler": 0, "target": {"node": 0, "path": ")" + path + R"("}}]})";
    };
    f.animations = "[" + channel(slide, "translation").insert(1, R"("name": "slide", )") + ", " +
                   channel(grow, "scale").insert(1, R"("name": "grow", )") + "]";
    return f.json();
}

}  // namespace arcomp::test
