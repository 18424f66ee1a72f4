#pragma once
// A unit quad in the xy plane (normal +z) as a glTF file with one embedded
// buffer and a 2x2 PNG (written by graph/io/GltfWriter), for tests of materials and vertex attributes. The
// buffer holds every attribute a test may name; a test picks the ones its
// primitive uses and writes the material it needs.
//
//   QuadGltf q;
//   q.materials = R"([{"normalTexture": {"index": 0}}])";
//   q.primitives = R"([{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 9, "material": 0}])";
//   const auto file = dir.write("quad.gltf", q.json());
//
// Accessors:
//   0 POSITION (0,0,0) (1,0,0) (1,1,0) (0,1,0)      1 NORMAL +z
//   2 TEXCOORD_0 as glTF exporters write it: u along +x, v down the image
//     (v = 1 - y)                                   3 TEXCOORD_1: u mirrored (1 - x), v = 1 - y
//   4 COLOR_0 VEC4 normalized unsigned bytes       5 COLOR_0 VEC3 floats
//   6 COLOR_0 VEC4 normalized unsigned shorts      7 TANGENT: -x at twice unit length, w -0.5
//   8 COLOR_0 VEC4 unsigned bytes, not normalized   9 indices (two triangles, counter-clockwise)

#include "graph/io/GltfWriter.hpp"

#include <cstdint>
#include <string>

namespace arcomp::test {

// A 2x2 RGBA PNG: red, green / blue, half-transparent white.
inline const char* kTinyPng =
    "iVBORw0KGgoAAAANSUhEUgAAAAIAAAACCAYAAABytg0kAAAAE0lEQVR4nGP4z8DwHwyBNAg0AABJSQl4KKDbdwAAAABJRU5ErkJggg==";

struct QuadGltf {
    std::string primitives =
        R"([{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 9, "material": 0}])";
    std::string materials = R"([{"name": "quad"}])";
    std::string textures = R"([{"source": 0}])";
    std::string samplers = "[]";
    std::string images = std::string(R"([{"uri": "data:image/png;base64,)") + kTinyPng + "\"}]";
    std::string extensionsUsed = "[]";
    std::string extensionsRequired = "[]";
    std::string nodes = R"([{"mesh": 0}])";
    std::string sceneNodes = "[0]";

    std::string json() const {
        using Json = GltfWriter::Json;
        GltfWriter w;
        const float positions[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
        const float normals[12] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
        const float uv0[8] = {0, 1, 1, 1, 1, 0, 0, 0};
        const float uv1[8] = {1, 1, 0, 1, 0, 0, 1, 0};
        const std::uint8_t colorsU8[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 0};
        const float colorsF32[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0.5f, 0.5f, 0.5f};
        const std::uint16_t colorsU16[16] = {65535, 0, 0, 65535, 0, 65535, 0, 65535, 0, 0, 65535, 65535, 0, 0, 0, 0};
        const float tangents[16] = {-2, 0, 0, -0.5f, -2, 0, 0, -0.5f, -2, 0, 0, -0.5f, -2, 0, 0, -0.5f};
        const std::uint16_t indices[6] = {0, 1, 2, 0, 2, 3};
        w.accessor(positions, 4, "VEC3", GltfWriter::kFloat);
        w.accessor(normals, 4, "VEC3", GltfWriter::kFloat);
        w.accessor(uv0, 4, "VEC2", GltfWriter::kFloat);
        w.accessor(uv1, 4, "VEC2", GltfWriter::kFloat);
        w.accessor(colorsU8, 4, "VEC4", GltfWriter::kUnsignedByte, {.normalized = true});
        w.accessor(colorsF32, 4, "VEC3", GltfWriter::kFloat);
        w.accessor(colorsU16, 4, "VEC4", GltfWriter::kUnsignedShort, {.normalized = true});
        w.accessor(tangents, 4, "VEC4", GltfWriter::kFloat);
        w.accessor(colorsU8, 4, "VEC4", GltfWriter::kUnsignedByte);
        w.accessor(indices, 6, "SCALAR", GltfWriter::kUnsignedShort);
        for (const Json& image : Json::parse(images)) w.image(image.dump());
        GltfWriter::add(w.meshes, R"({"primitives": )" + primitives + "}");
        w.materials = Json::parse(materials);
        w.textures = Json::parse(textures);
        w.samplers = Json::parse(samplers);
        w.extensionsUsed = Json::parse(extensionsUsed);
        w.extensionsRequired = Json::parse(extensionsRequired);
        w.nodes = Json::parse(nodes);
        w.sceneNodes = Json::parse(sceneNodes).get<std::vector<int>>();
        return w.text();
    }
};

}  // namespace arcomp::test
