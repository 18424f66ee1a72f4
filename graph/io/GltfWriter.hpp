#pragma once
// Writing a glTF 2.0 file as one .gltf text: the generated parts (the
// buffer, its views, the accessors, images) come from calls, the
// hand-written parts (materials, meshes, nodes, skins, animations, ...) as
// JSON text, so that the code that makes a model reads like the glTF it
// makes. The buffer and images are data URIs (graph/io/Base64.hpp): one file
// any viewer opens. For the feature models the glTF reference bench draws
// and the models tests write; reading glTF is GltfParser's job.
//
//   GltfWriter w;
//   const float corners[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
//   const std::uint16_t triangle[3] = {0, 1, 2};
//   const int position = w.accessor(corners, 3, "VEC3", GltfWriter::kFloat, {.bounds = true});
//   const int indices = w.accessor(triangle, 3, "SCALAR", GltfWriter::kUnsignedShort);
//   GltfWriter::add(w.meshes, R"({"primitives": [{"attributes": {"POSITION": )" + std::to_string(position) +
//                                 R"(}, "indices": )" + std::to_string(indices) + "}]}");
//   w.sceneNodes.push_back(GltfWriter::add(w.nodes, R"({"mesh": 0})"));
//   std::ofstream("triangle.gltf") << w.text();
//
//   GltfWriter d;  // the same triangle, Draco-compressed
//   const std::vector<std::uint32_t> corners3{0, 1, 2};
//   GltfWriter::add(d.meshes, R"({"primitives": [)" +
//                                 d.dracoPrimitive(3, {{.semantic = "POSITION", .data = corners, .components = 3,
//                                 .quantizationBits = 14}},
//                                                  corners3) + "]}");

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace arcomp {

// One float attribute of a primitive to compress with Draco.
struct DracoAttribute {
    std::string semantic;  // POSITION, NORMAL, TEXCOORD_0, ...
    const float* data = nullptr;
    int components = 3;
    int quantizationBits = 0;  // 0: kept as floats
};

struct GltfAccessorOptions {
    bool normalized = false;
    bool bounds = false;  // min and max, which POSITION and animation inputs must state (glTF 3.6.2.5); floats only
    int target = 0;       // the buffer view's target, 0 for none (animation and skin data)
};

class GltfWriter {
public:
    using Json = nlohmann::ordered_json;

    // glTF 2.0, 3.6.2.2 (component types) and 5.11 (buffer view targets).
    static constexpr int kByte = 5120, kUnsignedByte = 5121, kShort = 5122, kUnsignedShort = 5123, kUnsignedInt = 5125,
                         kFloat = 5126;
    static constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

    // The hand-written parts, each a JSON array; add() appends one element.
    Json materials = Json::array(), meshes = Json::array(), nodes = Json::array(), skins = Json::array(),
         animations = Json::array(), samplers = Json::array(), textures = Json::array();
    Json extensionsUsed = Json::array(), extensionsRequired = Json::array();
    std::vector<int> sceneNodes;  // scene 0's root nodes
    std::string generator = "arcomp";

    // Appends `json` (one JSON value as text) to `list` and gives its index.
    // Throws nlohmann::json::parse_error naming where the text is not JSON.
    static int add(Json& list, std::string_view json);

    // `count` elements of `type` (SCALAR, VEC2, VEC3, VEC4, MAT4) of
    // `componentType`, copied into the buffer from `data`, in a view of their
    // own that starts 4-byte aligned (3.6.2.4). Gives the accessor's index.
    int accessor(const void* data, std::size_t count, std::string_view type, int componentType,
                 GltfAccessorOptions options = {});
    // How many components an element of `type` has (SCALAR 1 ... MAT4 16);
    // throws std::invalid_argument for a type glTF does not have.
    static std::size_t components(std::string_view type);

    // A triangle primitive compressed with KHR_draco_mesh_compression by
    // libdraco's encoder (edgebreaker, or sequential, which keeps the
    // vertex order): its accessors declare the encoded counts and have no
    // buffer view, as exporters write them. Gives the primitive's JSON for
    // a mesh; the extension joins extensionsUsed and extensionsRequired.
    // Throws std::runtime_error when the encoder refuses the mesh.
    std::string dracoPrimitive(std::size_t vertexCount, const std::vector<DracoAttribute>& attributes,
                               const std::vector<std::uint32_t>& indices, bool sequential = false);

    // An image from the bytes of a PNG, or an image the JSON gives (a URI).
    int pngImage(const std::vector<std::uint8_t>& png);
    int image(std::string_view json);

    // The whole document, ending in a newline.
    std::string text() const;
    // The same as a GLB: the JSON chunk, then the buffer as the BIN chunk
    // (images stay data URIs).
    std::string glb() const;

private:
    Json document(bool embedBuffer) const;

    Json accessors_ = Json::array(), views_ = Json::array(), images_ = Json::array();
    std::vector<std::uint8_t> buffer_;
};

}  // namespace arcomp
