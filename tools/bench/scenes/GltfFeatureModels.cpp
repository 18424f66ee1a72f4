#include "tools/bench/scenes/GltfFeatureModels.hpp"

#include "graph/io/Base64.hpp"
#include "graph/io/GltfWriter.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_precision.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#include <webp/encode.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <numbers>
#include <stdexcept>

namespace arcomp {
namespace {

namespace fs = std::filesystem;
constexpr float kPi = std::numbers::pi_v<float>;

std::string num(float x) { return nlohmann::json(x).dump(); }
std::string vec(std::initializer_list<float> xs) {
    std::string s = "[";
    for (float x : xs) s += (s.size() > 1 ? "," : "") + num(x);
    return s + "]";
}
std::string vec(const glm::vec3& v) { return vec({v.x, v.y, v.z}); }

// graph/io/GltfWriter with the accessors the models use, typed, and their
// PNG textures.
class GltfBuilder : public GltfWriter {
public:
    GltfBuilder() { generator = "arcomp feature models"; }

    int scalars(const std::vector<float>& v, bool bounds) {
        return accessor(v.data(), v.size(), "SCALAR", kFloat, {.bounds = bounds});
    }
    int vec2s(const std::vector<glm::vec2>& v) {
        return accessor(glm::value_ptr(v[0]), v.size(), "VEC2", kFloat, {.target = kArrayBuffer});
    }
    int vec3s(const std::vector<glm::vec3>& v, bool bounds = false, int target = kArrayBuffer) {
        return accessor(glm::value_ptr(v[0]), v.size(), "VEC3", kFloat, {.bounds = bounds, .target = target});
    }
    int vec4s(const std::vector<glm::vec4>& v, int target = kArrayBuffer) {
        return accessor(glm::value_ptr(v[0]), v.size(), "VEC4", kFloat, {.target = target});
    }
    int mat4s(const std::vector<glm::mat4>& m) { return accessor(glm::value_ptr(m[0]), m.size(), "MAT4", kFloat); }
    int indices(const std::vector<std::uint16_t>& v) {
        return accessor(v.data(), v.size(), "SCALAR", kUnsignedShort, {.target = kElementArrayBuffer});
    }
    int joints(const std::vector<glm::u8vec4>& v) {
        return accessor(v.data(), v.size(), "VEC4", kUnsignedByte, {.target = kArrayBuffer});
    }
    // A texture of a PNG (from 8-bit BGR or BGRA) with its sampler.
    int texture(const cv::Mat& image, const std::string& sampler) {
        std::vector<std::uint8_t> png;
        if (!cv::imencode(".png", image, png)) throw std::runtime_error("feature model: cannot encode a PNG texture");
        const int source = pngImage(png);
        const int s = add(samplers, sampler);
        return add(textures, "{\"sampler\":" + std::to_string(s) + ",\"source\":" + std::to_string(source) + "}");
    }
};

struct MeshData {
    std::vector<glm::vec3> positions, normals, colors;
    std::vector<glm::vec2> uvs;
    std::vector<glm::u8vec4> joints;
    std::vector<glm::vec4> weights;
    std::vector<std::uint16_t> indices;
};

// A (columns x rows)-quad grid over u, v in [0, 1]; `at` gives position and
// normal. Seen from the normal's side u runs right and v down, as in a
// glTF texture, and triangles wind counter-clockwise.
template <typename At>
MeshData surface(int columns, int rows, At at) {
    MeshData m;
    for (int j = 0; j <= rows; ++j)
        for (int i = 0; i <= columns; ++i) {
            const glm::vec2 uv(static_cast<float>(i) / columns, static_cast<float>(j) / rows);
            const auto [p, n] = at(uv.x, uv.y);
            m.positions.push_back(p);
            m.normals.push_back(n);
            m.uvs.push_back(uv);
        }
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i) {
            const auto a = static_cast<std::uint16_t>(j * (columns + 1) + i);
            const auto b = static_cast<std::uint16_t>(a + 1), c = static_cast<std::uint16_t>(a + columns + 1),
                       d = static_cast<std::uint16_t>(c + 1);
            m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
        }
    return m;
}

struct Vertex {
    glm::vec3 position, normal;
};

// In the XY plane, facing +Z.
MeshData plane(float size, int segments = 1) {
    return surface(segments, segments, [size](float u, float v) {
        return Vertex{{(u - 0.5f) * size, (0.5f - v) * size, 0.0f}, {0.0f, 0.0f, 1.0f}};
    });
}

// u = 0 faces +Z; v runs from the north pole (+Y) down.
MeshData sphere(float radius, int segments = 48, int rings = 24) {
    return surface(segments, rings, [radius](float u, float v) {
        const float theta = v * kPi, phi = u * 2.0f * kPi;
        const glm::vec3 n(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi));
        return Vertex{radius * n, n};
    });
}

// Open, along Y from +height/2 down to -height/2.
MeshData cylinder(float radius, float height, int segments, int rings) {
    return surface(segments, rings, [=](float u, float v) {
        const float phi = u * 2.0f * kPi;
        const glm::vec3 n(std::sin(phi), 0.0f, std::cos(phi));
        return Vertex{radius * n + glm::vec3(0.0f, (0.5f - v) * height, 0.0f), n};
    });
}

MeshData box(const glm::vec3& half) {
    // Each face: its normal, then right and up as seen from outside (right x up = normal).
    const glm::vec3 faces[6][3] = {{{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
                                   {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
                                   {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}};
    MeshData m;
    for (const auto& [n, right, up] : faces) {
        const auto first = static_cast<std::uint16_t>(m.positions.size());
        for (const glm::vec2 corner : {glm::vec2(-1, 1), glm::vec2(1, 1), glm::vec2(-1, -1), glm::vec2(1, -1)}) {
            m.positions.push_back((n + corner.x * right + corner.y * up) * half);
            m.normals.push_back(n);
            m.uvs.push_back({corner.x * 0.5f + 0.5f, 0.5f - corner.y * 0.5f});
        }
        for (int k : {0, 2, 1, 1, 2, 3}) m.indices.push_back(static_cast<std::uint16_t>(first + k));
    }
    return m;
}

// The "attributes" and "indices" of a primitive, its accessors added once
// so that several primitives can share them.
std::string primitiveData(GltfBuilder& b, const MeshData& m) {
    std::string a = "\"attributes\":{\"POSITION\":" + std::to_string(b.vec3s(m.positions, true)) +
                    ",\"NORMAL\":" + std::to_string(b.vec3s(m.normals));
    if (!m.uvs.empty()) a += ",\"TEXCOORD_0\":" + std::to_string(b.vec2s(m.uvs));
    if (!m.colors.empty()) a += ",\"COLOR_0\":" + std::to_string(b.vec3s(m.colors));
    if (!m.joints.empty()) a += ",\"JOINTS_0\":" + std::to_string(b.joints(m.joints));
    if (!m.weights.empty()) a += ",\"WEIGHTS_0\":" + std::to_string(b.vec4s(m.weights));
    return a + "},\"indices\":" + std::to_string(b.indices(m.indices));
}

int mesh(GltfBuilder& b, const std::string& data, int material) {
    return GltfBuilder::add(b.meshes,
                            "{\"primitives\":[{" + data + ",\"material\":" + std::to_string(material) + "}]}");
}

int meshNode(GltfBuilder& b, const std::string& name, int meshIndex, const glm::vec3& translation = glm::vec3(0.0f)) {
    std::string json = "{\"name\":\"" + name + "\",\"mesh\":" + std::to_string(meshIndex);
    if (translation != glm::vec3(0.0f)) json += ",\"translation\":" + vec(translation);
    return GltfBuilder::add(b.nodes, json + "}");
}

const std::string kRepeatSampler = R"({"magFilter":9729,"minFilter":9987,"wrapS":10497,"wrapT":10497})";
const std::string kClampSampler = R"({"magFilter":9729,"minFilter":9987,"wrapS":33071,"wrapT":33071})";

std::string emissive() {
    GltfBuilder b;
    const int m =
        GltfBuilder::add(b.materials, R"({"name":"glow","pbrMetallicRoughness":{"baseColorFactor":[0,0,0,1],)"
                                      R"("metallicFactor":0,"roughnessFactor":1},"emissiveFactor":[1,0.45,0.1]})");
    b.sceneNodes.push_back(meshNode(b, "sphere", mesh(b, primitiveData(b, sphere(0.8f)), m)));
    return b.text();
}

// Some exported models (car lamps among them) mark a lamp unlit and leave
// its colour in emissiveFactor over a black base colour.
// KHR_materials_unlit draws the base colour only, so the lamp is black.
std::string emissiveUnlit() {
    GltfBuilder b;
    b.extensionsUsed.push_back("KHR_materials_unlit");
    const int m =
        GltfBuilder::add(b.materials, R"({"name":"lamp","pbrMetallicRoughness":{"baseColorFactor":[0,0,0,1]},)"
                                      R"("emissiveFactor":[1,0.05,0.02],"extensions":{"KHR_materials_unlit":{}}})");
    const int body =
        GltfBuilder::add(b.materials, R"({"name":"body","pbrMetallicRoughness":{"baseColorFactor":[0.6,0.6,0.65,1],)"
                                      R"("metallicFactor":0,"roughnessFactor":0.5}})");
    b.sceneNodes.push_back(meshNode(b, "body", mesh(b, primitiveData(b, box({0.9f, 0.5f, 0.3f})), body)));
    b.sceneNodes.push_back(
        meshNode(b, "lamp", mesh(b, primitiveData(b, box({0.25f, 0.12f, 0.05f})), m), {0.45f, 0.1f, 0.32f}));
    return b.text();
}

// A 4 x 4 grid of round bumps as a tangent-space normal map (+X right, +Y
// up in the image, glTF's convention). No TANGENT attribute: the viewer
// generates tangents.
std::string normalMap() {
    const int size = 256, cells = 4;
    cv::Mat1f height(size, size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const float cell = static_cast<float>(size) / cells;
            const float dx = std::fmod(static_cast<float>(x) + 0.5f, cell) / cell - 0.5f;
            const float dy = std::fmod(static_cast<float>(y) + 0.5f, cell) / cell - 0.5f;
            const float d = std::sqrt(dx * dx + dy * dy) / 0.4f;
            height(y, x) = d < 1.0f ? std::pow(std::cos(d * kPi / 2.0f), 2.0f) : 0.0f;
        }
    cv::Mat3b normals(size, size);
    const float strength = 12.0f;  // height units per texture width, as a slope scale
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const float hx = (height(y, std::min(x + 1, size - 1)) - height(y, std::max(x - 1, 0))) * 0.5f;
            const float hRow = (height(std::min(y + 1, size - 1), x) - height(std::max(y - 1, 0), x)) * 0.5f;
            // Image rows run down, the map's +Y up.
            const glm::vec3 n = glm::normalize(glm::vec3(-strength * hx, strength * hRow, 1.0f));
            const glm::vec3 encoded = (n * 0.5f + 0.5f) * 255.0f + 0.5f;
            normals(y, x) = cv::Vec3b(static_cast<std::uint8_t>(encoded.z), static_cast<std::uint8_t>(encoded.y),
                                      static_cast<std::uint8_t>(encoded.x));  // BGR
        }
    GltfBuilder b;
    const int t = b.texture(normals, kRepeatSampler);
    const int m =
        GltfBuilder::add(b.materials, R"({"name":"bumps","pbrMetallicRoughness":{"baseColorFactor":[0.8,0.8,0.8,1],)"
                                      R"("metallicFactor":0,"roughnessFactor":0.45},"normalTexture":{"index":)" +
                                          std::to_string(t) + "}}");
    b.sceneNodes.push_back(meshNode(b, "plane", mesh(b, primitiveData(b, plane(2.0f)), m)));
    return b.text();
}

// Alpha rises from 0 at the top-left corner to 1 at the bottom-right; the
// 0.5 cutoff cuts the plane along the other diagonal.
std::string alphaMask() {
    const int size = 128;
    cv::Mat4b texture(size, size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const bool light = ((x / 16) + (y / 16)) % 2 == 0;
            const auto alpha = static_cast<std::uint8_t>((x + y) * 255 / (2 * (size - 1)));
            texture(y, x) = light ? cv::Vec4b(40, 140, 230, alpha) : cv::Vec4b(20, 60, 120, alpha);  // BGRA
        }
    GltfBuilder b;
    const int t = b.texture(texture, kClampSampler);
    const int m = GltfBuilder::add(
        b.materials, R"({"name":"cutout","pbrMetallicRoughness":{"baseColorTexture":{"index":)" + std::to_string(t) +
                         R"(},"metallicFactor":0,"roughnessFactor":0.7},)"
                         R"("alphaMode":"MASK","alphaCutoff":0.5,"doubleSided":true})");
    b.sceneNodes.push_back(meshNode(b, "plane", mesh(b, primitiveData(b, plane(2.0f)), m)));
    return b.text();
}

// A half-transparent blue plane over part of an opaque yellow sphere.
std::string alphaBlend() {
    GltfBuilder b;
    const int opaque =
        GltfBuilder::add(b.materials, R"({"name":"opaque","pbrMetallicRoughness":{"baseColorFactor":[0.9,0.7,0.1,1],)"
                                      R"("metallicFactor":0,"roughnessFactor":0.5}})");
    const int glass = GltfBuilder::add(
        b.materials, R"({"name":"glass","pbrMetallicRoughness":{"baseColorFactor":[0.1,0.3,0.9,0.5],)"
                     R"("metallicFactor":0,"roughnessFactor":0.5},"alphaMode":"BLEND","doubleSided":true})");
    b.sceneNodes.push_back(
        meshNode(b, "sphere", mesh(b, primitiveData(b, sphere(0.7f)), opaque), {-0.2f, 0.0f, -0.4f}));
    b.sceneNodes.push_back(meshNode(b, "pane", mesh(b, primitiveData(b, plane(1.4f)), glass), {0.45f, -0.1f, 0.4f}));
    return b.text();
}

// A checker with a red cell at its top-left corner (so that a flip or a turn
// shows), offset, turned and scaled uniformly: three.js applies a
// non-uniform scale in another order than KHR_texture_transform states.
std::string textureTransform() {
    const int size = 256, cell = 32;
    cv::Mat3b checker(size, size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const bool light = ((x / cell) + (y / cell)) % 2 == 0;
            checker(y, x) = x < cell && y < cell ? cv::Vec3b(30, 30, 220)
                            : light              ? cv::Vec3b(235, 235, 235)
                                                 : cv::Vec3b(120, 50, 30);
        }
    GltfBuilder b;
    b.extensionsUsed.push_back("KHR_texture_transform");
    const int t = b.texture(checker, kRepeatSampler);
    const int m = GltfBuilder::add(
        b.materials,
        R"({"name":"checker","pbrMetallicRoughness":{"baseColorTexture":{"index":)" + std::to_string(t) +
            R"(,"extensions":{"KHR_texture_transform":{"offset":[0.1,0.2],"rotation":0.3,"scale":[1.5,1.5]}}},)"
            R"("metallicFactor":0,"roughnessFactor":0.8}})");
    b.sceneNodes.push_back(meshNode(b, "plane", mesh(b, primitiveData(b, plane(2.0f)), m)));
    return b.text();
}

// Two rows of five spheres: dielectric above, metal below; roughness 0,
// 0.25, 0.5, 0.75, 1 from left to right.
std::string metalRoughSweep() {
    GltfBuilder b;
    const std::string data = primitiveData(b, sphere(0.4f));
    for (int row = 0; row < 2; ++row)
        for (int column = 0; column < 5; ++column) {
            const float roughness = static_cast<float>(column) / 4.0f;
            const int m = GltfBuilder::add(b.materials,
                                           "{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.9,0.6,0.3,1],"
                                           "\"metallicFactor\":" +
                                               std::to_string(row) + ",\"roughnessFactor\":" + num(roughness) + "}}");
            b.sceneNodes.push_back(meshNode(b, "sphere", mesh(b, data, m),
                                            {static_cast<float>(column - 2), row == 0 ? 0.5f : -0.5f, 0.0f}));
        }
    return b.text();
}

// COLOR_0 from the normal: every direction its own colour.
std::string vertexColors() {
    MeshData s = sphere(0.8f);
    for (const glm::vec3& n : s.normals) s.colors.push_back(n * 0.5f + 0.5f);
    GltfBuilder b;
    const int m =
        GltfBuilder::add(b.materials, R"({"name":"white","pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1],)"
                                      R"("metallicFactor":0,"roughnessFactor":0.6}})");
    b.sceneNodes.push_back(meshNode(b, "sphere", mesh(b, primitiveData(b, s), m)));
    return b.text();
}

// A slab that moves left to right, lifting in the middle, and turns half a
// turn about a tilted axis over 2 s; LINEAR keys at 0, 1 and 2 s.
std::string animatedNode() {
    GltfBuilder b;
    const int m =
        GltfBuilder::add(b.materials, R"({"name":"slab","pbrMetallicRoughness":{"baseColorFactor":[0.2,0.6,0.3,1],)"
                                      R"("metallicFactor":0,"roughnessFactor":0.5}})");
    const int node = meshNode(b, "slab", mesh(b, primitiveData(b, box({0.6f, 0.3f, 0.15f})), m), {-0.8f, 0.0f, 0.0f});
    b.sceneNodes.push_back(node);
    const int times = b.scalars({0.0f, 1.0f, 2.0f}, true);
    const std::vector<glm::vec3> translations = {{-0.8f, 0.0f, 0.0f}, {0.0f, 0.4f, 0.0f}, {0.8f, 0.0f, 0.0f}};
    const glm::vec3 axis = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f));
    std::vector<glm::vec4> rotations;
    for (float turn : {0.0f, 0.25f, 0.5f}) {
        const glm::quat q = glm::angleAxis(turn * 2.0f * kPi, axis);
        rotations.push_back({q.x, q.y, q.z, q.w});
    }
    const int translation = b.vec3s(translations, false, 0), rotation = b.vec4s(rotations, 0);
    GltfBuilder::add(b.animations, "{\"name\":\"move\",\"samplers\":[{\"input\":" + std::to_string(times) +
                                       ",\"output\":" + std::to_string(translation) +
                                       ",\"interpolation\":\"LINEAR\"},{\"input\":" + std::to_string(times) +
                                       ",\"output\":" + std::to_string(rotation) +
                                       ",\"interpolation\":\"LINEAR\"}],\"channels\":["
                                       "{\"sampler\":0,\"target\":{\"node\":" +
                                       std::to_string(node) +
                                       ",\"path\":\"translation\"}},"
                                       "{\"sampler\":1,\"target\":{\"node\":" +
                                       std::to_string(node) + ",\"path\":\"rotation\"}}]}");
    return b.text();
}

// A cylinder on two joints, the lower at its base, the upper at its middle;
// the weights cross over around the middle, and the upper joint turns a
// quarter turn about Z over 2 s.
std::string skinnedBend() {
    MeshData c = cylinder(0.2f, 2.0f, 24, 32);
    for (const glm::vec3& p : c.positions) {
        const float w = glm::smoothstep(-0.3f, 0.3f, p.y);
        // A joint with no weight must be 0 (glTF 2.0, 3.7.3.3): one joint where one has it all.
        if (w == 0.0f || w == 1.0f) {
            c.joints.push_back({w == 0.0f ? 0 : 1, 0, 0, 0});
            c.weights.push_back({1.0f, 0.0f, 0.0f, 0.0f});
        } else {
            c.joints.push_back({0, 1, 0, 0});
            c.weights.push_back({1.0f - w, w, 0.0f, 0.0f});
        }
    }
    GltfBuilder b;
    const int m =
        GltfBuilder::add(b.materials, R"({"name":"tube","pbrMetallicRoughness":{"baseColorFactor":[0.8,0.3,0.5,1],)"
                                      R"("metallicFactor":0,"roughnessFactor":0.5},"doubleSided":true})");
    const int meshIndex = mesh(b, primitiveData(b, c), m);
    // Nodes: 0 the skinned mesh, 1 the base joint at y = -1, 2 the bending joint at y = 0.
    b.sceneNodes = {0, 1};
    GltfBuilder::add(b.nodes, "{\"name\":\"tube\",\"mesh\":" + std::to_string(meshIndex) + ",\"skin\":0}");
    GltfBuilder::add(b.nodes, R"({"name":"base","translation":[0,-1,0],"children":[2]})");
    GltfBuilder::add(b.nodes, R"({"name":"bend","translation":[0,1,0]})");
    const int inverseBind =
        b.mat4s({glm::inverse(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -1.0f, 0.0f))), glm::mat4(1.0f)});
    GltfBuilder::add(b.skins,
                     "{\"inverseBindMatrices\":" + std::to_string(inverseBind) + ",\"joints\":[1,2],\"skeleton\":1}");
    const int times = b.scalars({0.0f, 2.0f}, true);
    const glm::quat start(1.0f, 0.0f, 0.0f, 0.0f), end = glm::angleAxis(kPi / 2.0f, glm::vec3(0.0f, 0.0f, 1.0f));
    const int rotation = b.vec4s({{start.x, start.y, start.z, start.w}, {end.x, end.y, end.z, end.w}}, 0);
    GltfBuilder::add(b.animations, "{\"name\":\"bend\",\"samplers\":[{\"input\":" + std::to_string(times) +
                                       ",\"output\":" + std::to_string(rotation) +
                                       ",\"interpolation\":\"LINEAR\"}],\"channels\":[{\"sampler\":0,"
                                       "\"target\":{\"node\":2,\"path\":\"rotation\"}}]}");
    return b.text();
}

// A checker on a ball: the texture shows where each texture coordinate
// went, the shading where each normal went, so the compressed copies show
// what decoding got wrong.
cv::Mat ballChecker() {
    cv::Mat3b checker(128, 256);
    for (int y = 0; y < checker.rows; ++y)
        for (int x = 0; x < checker.cols; ++x)
            checker(y, x) = ((x / 16) + (y / 16)) % 2 == 0 ? cv::Vec3b(40, 160, 230) : cv::Vec3b(230, 230, 230);
    return checker;
}

int ballMaterial(GltfBuilder& b) {
    const int t = b.texture(ballChecker(), kRepeatSampler);
    return GltfBuilder::add(b.materials, R"({"name":"checker","pbrMetallicRoughness":{"baseColorTexture":{"index":)" +
                                             std::to_string(t) + R"(},"metallicFactor":0,"roughnessFactor":0.5}})");
}

std::string checkerBall() {
    GltfBuilder b;
    const int m = ballMaterial(b);
    b.sceneNodes.push_back(meshNode(b, "ball", mesh(b, primitiveData(b, sphere(0.9f)), m)));
    return b.text();
}

// The same ball, its primitive compressed by libdraco as exporters do:
// 14-bit positions, 10-bit normals, 12-bit texture coordinates.
std::string checkerBallDraco() {
    GltfBuilder b;
    const int m = ballMaterial(b);
    const MeshData ball = sphere(0.9f);
    const std::vector<std::uint32_t> indices(ball.indices.begin(), ball.indices.end());
    std::string primitive = b.dracoPrimitive(
        ball.positions.size(),
        {{.semantic = "POSITION", .data = &ball.positions[0].x, .components = 3, .quantizationBits = 14},
         {.semantic = "NORMAL", .data = &ball.normals[0].x, .components = 3, .quantizationBits = 10},
         {.semantic = "TEXCOORD_0", .data = &ball.uvs[0].x, .components = 2, .quantizationBits = 12}},
        indices);
    primitive.insert(primitive.size() - 1, ",\"material\":" + std::to_string(m));
    const int meshIndex = GltfBuilder::add(b.meshes, "{\"primitives\":[" + primitive + "]}");
    b.sceneNodes.push_back(meshNode(b, "ball", meshIndex));
    return b.text();
}

// A plane with a lossless WebP texture (EXT_texture_webp, required: no PNG
// fallback), a gradient under a checker so that both colour and edges show.
std::string webpPlane() {
    const int w = 128, h = 128;
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(w) * h * 4);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint8_t* p = &rgba[(static_cast<std::size_t>(y) * w + x) * 4];
            const bool dark = ((x / 32) + (y / 32)) % 2 == 1;
            p[0] = static_cast<std::uint8_t>(dark ? 40 : 60 + x * 3 / 2);
            p[1] = static_cast<std::uint8_t>(dark ? 40 : 60 + y * 3 / 2);
            p[2] = static_cast<std::uint8_t>(dark ? 120 : 200);
            p[3] = 255;
        }
    std::uint8_t* encoded = nullptr;
    const std::size_t size = WebPEncodeLosslessRGBA(rgba.data(), w, h, w * 4, &encoded);
    if (size == 0) throw std::runtime_error("feature model: libwebp cannot encode the plane's texture");
    const std::string uri = "data:image/webp;base64," + base64(encoded, size);
    WebPFree(encoded);
    GltfBuilder b;
    b.extensionsUsed.push_back("EXT_texture_webp");
    b.extensionsRequired.push_back("EXT_texture_webp");
    const int image = b.image(R"({"uri":")" + uri + R"("})");
    const int sampler = GltfBuilder::add(b.samplers, kClampSampler);
    const int t = GltfBuilder::add(b.textures, R"({"sampler":)" + std::to_string(sampler) +
                                                   R"(,"extensions":{"EXT_texture_webp":{"source":)" +
                                                   std::to_string(image) + "}}}");
    const int m =
        GltfBuilder::add(b.materials, R"({"name":"webp","pbrMetallicRoughness":{"baseColorTexture":{"index":)" +
                                          std::to_string(t) + R"(},"metallicFactor":0,"roughnessFactor":0.9}})");
    b.sceneNodes.push_back(meshNode(b, "plane", mesh(b, primitiveData(b, plane(2.0f)), m)));
    return b.text();
}

// Runs gltfpack with an argument list, no shell: its exit status, or -1
// when it cannot be started.
int runGltfpack(const std::vector<std::string>& arguments) {
    std::vector<char*> argv;
    std::vector<std::string> owned{"gltfpack"};
    owned.insert(owned.end(), arguments.begin(), arguments.end());
    for (std::string& a : owned) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    if (posix_spawnp(&pid, "gltfpack", nullptr, nullptr, argv.data(), environ) != 0) return -1;
    int status = 0;
    if (waitpid(pid, &status, 0) != pid) return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

struct Entry {
    FeatureModel model;
    std::string (*gltf)();
};

// Light from above, right and in front of the camera, so that every
// model shows a lit and a shaded side.
const FeatureLight kKeyLight{glm::normalize(glm::vec3(0.5f, 0.8f, 0.6f)), glm::vec3(1.0f), 2.0f};
// From the upper left and low, so that bumps cast their slopes.
const FeatureLight kGrazingLight{glm::normalize(glm::vec3(-0.7f, 0.5f, 0.4f)), glm::vec3(1.0f), 2.0f};

const std::vector<Entry>& entries() {
    static const std::vector<Entry> all = {
        {{"emissive", "black base colour, orange emissiveFactor, lit", {{0, 0, 3}, {0, 0, 0}}, kKeyLight, "neutral"},
         emissive},
        {{"emissive-unlit",
          "KHR_materials_unlit lamp with black base colour and its colour in emissiveFactor (drawn black)",
          {{1.2f, 0.8f, 3.0f}, {0, 0, 0}},
          kKeyLight,
          "neutral"},
         emissiveUnlit},
        {{"normal-map",
          "bump normal map on a plane, tangents generated",
          {{0, 1.0f, 2.8f}, {0, 0, 0}},
          kGrazingLight,
          "neutral"},
         normalMap},
        {{"alpha-mask",
          "MASK with cutoff 0.5 over a diagonal alpha gradient",
          {{0, 0, 3}, {0, 0, 0}},
          kKeyLight,
          "neutral"},
         alphaMask},
        {{"alpha-blend", "BLEND pane in front of an opaque sphere", {{0, 0.3f, 3.2f}, {0, 0, 0}}, kKeyLight, "neutral"},
         alphaBlend},
        {{"texture-transform",
          "KHR_texture_transform: offset, rotation, uniform scale",
          {{0, 0, 3}, {0, 0, 0}},
          kKeyLight,
          "neutral"},
         textureTransform},
        {{"metal-rough",
          "metallic 0 (top) and 1 (bottom), roughness 0 to 1 (left to right)",
          {{0, 0, 5.5f}, {0, 0, 0}},
          kKeyLight,
          "neutral"},
         metalRoughSweep},
        {{"vertex-colors", "COLOR_0 times a white base colour", {{0, 0, 3}, {0, 0, 0}}, kKeyLight, "neutral"},
         vertexColors},
        {{"animated-node",
          "translation and rotation, LINEAR, over 2 s",
          {{0, 0.8f, 3.2f}, {0, 0.1f, 0}},
          kKeyLight,
          "neutral",
          1.0f,
          {0.0f, 0.5f, 1.25f, 2.0f}},
         animatedNode},
        {{"skinned-bend",
          "two-joint skin bending a cylinder a quarter turn over 2 s",
          {{0, 0, 3.6f}, {-0.3f, 0, 0}},
          kKeyLight,
          "neutral",
          1.0f,
          {0.0f, 1.0f, 2.0f}},
         skinnedBend},
        {{"checker-ball",
          "a checker-textured ball, the source of the compressed copies",
          {{0, 0, 3}, {0, 0, 0}},
          kKeyLight,
          "neutral"},
         checkerBall},
        {{"checker-ball-draco",
          "the ball, KHR_draco_mesh_compression (14/10/12-bit)",
          {{0, 0, 3}, {0, 0, 0}},
          kKeyLight,
          "neutral"},
         checkerBallDraco},
        {{"checker-ball-meshopt",
          "the ball, EXT_meshopt_compression by gltfpack -c -noq",
          {{0, 0, 3}, {0, 0, 0}},
          kKeyLight,
          "neutral",
          1.0f,
          {},
          "checker-ball",
          "-c -noq"},
         nullptr},
        {{"checker-ball-quantized",
          "the ball, KHR_mesh_quantization by gltfpack",
          {{0, 0, 3}, {0, 0, 0}},
          kKeyLight,
          "neutral",
          1.0f,
          {},
          "checker-ball",
          ""},
         nullptr},
        {{"webp-plane", "EXT_texture_webp, a lossless WebP texture", {{0, 0, 3}, {0, 0, 0}}, kKeyLight, "neutral"},
         webpPlane},
    };
    return all;
}

}  // namespace

const std::vector<FeatureModel>& featureModels() {
    static const std::vector<FeatureModel> models = [] {
        std::vector<FeatureModel> out;
        for (const Entry& e : entries()) out.push_back(e.model);
        return out;
    }();
    return models;
}

std::string featureModelGltf(const std::string& name) {
    for (const Entry& e : entries())
        if (e.model.name == name) {
            if (!e.gltf)
                throw std::invalid_argument("feature model '" + name + "' is gltfpack's copy of " + e.model.packedFrom);
            return e.gltf();
        }
    throw std::invalid_argument("no feature model named '" + name + "'");
}

fs::path writeFeatureModel(const FeatureModel& model, const fs::path& folder) {
    if (!model.packedFrom.empty()) {
        const auto& all = featureModels();
        const auto from =
            std::find_if(all.begin(), all.end(), [&](const FeatureModel& m) { return m.name == model.packedFrom; });
        if (from == all.end()) throw std::invalid_argument("no feature model named '" + model.packedFrom + "'");
        const fs::path source = writeFeatureModel(*from, folder);
        const fs::path file = folder / (model.name + ".glb");
        std::vector<std::string> arguments{"-i", source.string(), "-o", file.string()};
        for (std::size_t at = 0; at < model.packOptions.size();) {
            const std::size_t end = std::min(model.packOptions.find(' ', at), model.packOptions.size());
            if (end > at) arguments.push_back(model.packOptions.substr(at, end - at));
            at = end + 1;
        }
        if (const int status = runGltfpack(arguments); status != 0)
            throw std::runtime_error("cannot make feature model " + file.string() + ": gltfpack " +
                                     (status < 0 ? "is not installed (Debian: gltfpack; scripts/setup installs it)"
                                                 : "exited with " + std::to_string(status)));
        return file;
    }
    const std::string text = featureModelGltf(model.name);
    std::error_code ec;
    fs::create_directories(folder, ec);
    const fs::path file = folder / (model.name + ".gltf");
    std::ofstream out(file, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw std::runtime_error("cannot write feature model " + file.string());
    return file;
}

}  // namespace arcomp
