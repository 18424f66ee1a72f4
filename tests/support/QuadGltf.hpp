#pragma once
// A unit quad in the xy plane (normal +z) as a glTF file with one embedded
// buffer and a 2x2 PNG, for tests of materials and vertex attributes. The
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

#include "graph/io/Base64.hpp"
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

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

    struct View {
        std::size_t offset, length;
    };

    static std::vector<unsigned char> bytes(std::vector<View>& views) {
        std::vector<unsigned char> b;
        const auto add = [&](const void* data, std::size_t size) {
            views.push_back({b.size(), size});
            const auto* p = static_cast<const unsigned char*>(data);
            b.insert(b.end(), p, p + size);
            b.resize((b.size() + 3) / 4 * 4, 0);
        };
        const float positions[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
        const float normals[12] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
        const float uv0[8] = {0, 1, 1, 1, 1, 0, 0, 0};
        const float uv1[8] = {1, 1, 0, 1, 0, 0, 1, 0};
        const std::uint8_t colorsU8[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 0};
        const float colorsF32[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0.5f, 0.5f, 0.5f};
        const std::uint16_t colorsU16[16] = {65535, 0, 0, 65535, 0, 65535, 0, 65535, 0, 0, 65535, 65535, 0, 0, 0, 0};
        const float tangents[16] = {-2, 0, 0, -0.5f, -2, 0, 0, -0.5f, -2, 0, 0, -0.5f, -2, 0, 0, -0.5f};
        const std::uint16_t indices[6] = {0, 1, 2, 0, 2, 3};
        add(positions, sizeof positions);
        add(normals, sizeof normals);
        add(uv0, sizeof uv0);
        add(uv1, sizeof uv1);
        add(colorsU8, sizeof colorsU8);
        add(colorsF32, sizeof colorsF32);
        add(colorsU16, sizeof colorsU16);
        add(tangents, sizeof tangents);
        add(colorsU8, sizeof colorsU8);
        add(indices, sizeof indices);
        return b;
    }

    std::string json() const {
        std::vector<View> views;
        const std::vector<unsigned char> b = bytes(views);
        std::string bufferViews, accessors;
        const char* kinds[10][3] = {{"5126", "VEC3", "false"}, {"5126", "VEC3", "false"}, {"5126", "VEC2", "false"},
                                    {"5126", "VEC2", "false"}, {"5121", "VEC4", "true"},  {"5126", "VEC3", "false"},
                                    {"5123", "VEC4", "true"},  {"5126", "VEC4", "false"}, {"5121", "VEC4", "false"},
                                    {"5123", "SCALAR", "false"}};
        for (std::size_t i = 0; i < views.size(); ++i) {
            bufferViews += std::string(i ? ", " : "") + R"({"buffer": 0, "byteOffset": )" + std::to_string(views[i].offset) +
                           R"(, "byteLength": )" + std::to_string(views[i].length) + "}";
            accessors += std::string(i ? ", " : "") + R"({"bufferView": )" + std::to_string(i) + R"(, "componentType": )" +
                         kinds[i][0] + R"(, "normalized": )" + kinds[i][2] + R"(, "count": )" + (i == 9 ? "6" : "4") +
                         R"(, "type": ")" + kinds[i][1] + "\"}";
        }
        return R"({"asset": {"version": "2.0"}, "extensionsUsed": )" + extensionsUsed +
               R"(, "extensionsRequired": )" + extensionsRequired +
               R"(, "scene": 0, "scenes": [{"nodes": )" + sceneNodes + R"(}], "nodes": )" + nodes + R"(,
  "meshes": [{"primitives": )" + primitives + R"(}],
  "materials": )" + materials + R"(, "textures": )" + textures + R"(, "samplers": )" + samplers +
               R"(, "images": )" + images + R"(,
  "accessors": [)" + accessors + R"(], "bufferViews": [)" + bufferViews + R"(],
  "buffers": [{"byteLength": )" + std::to_string(b.size()) + R"(, "uri": "data:application/octet-stream;base64,)" +
               base64(b) + "\"}]}";
    }
};

} // namespace arcomp::test
