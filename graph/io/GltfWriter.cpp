#include "graph/io/GltfWriter.hpp"

#include "graph/io/Base64.hpp"

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

namespace arcomp {

namespace {

std::size_t bytesOf(int componentType) {
    switch (componentType) {
    case GltfWriter::kByte:
    case GltfWriter::kUnsignedByte: return 1;
    case GltfWriter::kShort:
    case GltfWriter::kUnsignedShort: return 2;
    case GltfWriter::kUnsignedInt:
    case GltfWriter::kFloat: return 4;
    }
    throw std::invalid_argument("glTF writer: no component type " + std::to_string(componentType));
}

}  // namespace

std::size_t GltfWriter::components(std::string_view type) {
    if (type == "SCALAR") return 1;
    if (type == "VEC2") return 2;
    if (type == "VEC3") return 3;
    if (type == "VEC4" || type == "MAT2") return 4;
    if (type == "MAT3") return 9;
    if (type == "MAT4") return 16;
    throw std::invalid_argument("glTF writer: no accessor type " + std::string(type));
}

int GltfWriter::add(Json& list, std::string_view json) {
    list.push_back(Json::parse(json));
    return static_cast<int>(list.size()) - 1;
}

int GltfWriter::accessor(const void* data, std::size_t count, std::string_view type, int componentType,
                         GltfAccessorOptions options) {
    const std::size_t components = GltfWriter::components(type);
    const std::size_t bytes = count * components * bytesOf(componentType);
    buffer_.resize((buffer_.size() + 3) / 4 * 4, 0);
    const std::size_t offset = buffer_.size();
    buffer_.resize(offset + bytes);
    if (bytes) std::memcpy(buffer_.data() + offset, data, bytes);
    Json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}};
    if (options.target) view["target"] = options.target;
    views_.push_back(std::move(view));

    Json a = {{"bufferView", views_.size() - 1}, {"componentType", componentType}};
    if (options.normalized) a["normalized"] = true;
    a["count"] = count;
    a["type"] = type;
    if (options.bounds) {
        if (componentType != kFloat) throw std::invalid_argument("glTF writer: bounds are written for floats only");
        const auto* values = static_cast<const float*>(data);
        std::vector<float> lo(values, values + components), hi = lo;
        for (std::size_t i = 0; i < count; ++i)
            for (std::size_t c = 0; c < components; ++c) {
                lo[c] = std::min(lo[c], values[i * components + c]);
                hi[c] = std::max(hi[c], values[i * components + c]);
            }
        a["min"] = lo;
        a["max"] = hi;
    }
    accessors_.push_back(std::move(a));
    return static_cast<int>(accessors_.size()) - 1;
}

std::string GltfWriter::dracoPrimitive(std::size_t vertexCount, const std::vector<DracoAttribute>& attributes,
                                       const std::vector<std::uint32_t>& indices, bool sequential) {
    draco::Mesh mesh;
    mesh.set_num_points(static_cast<std::uint32_t>(vertexCount));
    mesh.SetNumFaces(indices.size() / 3);
    for (std::size_t f = 0; f < indices.size() / 3; ++f)
        mesh.SetFace(draco::FaceIndex(static_cast<std::uint32_t>(f)),
                     {draco::PointIndex(indices[f * 3]), draco::PointIndex(indices[f * 3 + 1]),
                      draco::PointIndex(indices[f * 3 + 2])});
    draco::Encoder encoder;
    std::vector<int> ids;
    for (const DracoAttribute& a : attributes) {
        const auto type = a.semantic == "POSITION"             ? draco::GeometryAttribute::POSITION
                          : a.semantic == "NORMAL"             ? draco::GeometryAttribute::NORMAL
                          : a.semantic.starts_with("TEXCOORD") ? draco::GeometryAttribute::TEX_COORD
                          : a.semantic.starts_with("COLOR")    ? draco::GeometryAttribute::COLOR
                                                               : draco::GeometryAttribute::GENERIC;
        draco::GeometryAttribute g;
        g.Init(type, nullptr, static_cast<std::uint8_t>(a.components), draco::DT_FLOAT32, false,
               static_cast<std::int64_t>(sizeof(float)) * a.components, 0);
        const int id = mesh.AddAttribute(g, true, static_cast<std::uint32_t>(vertexCount));
        for (std::size_t v = 0; v < vertexCount; ++v)
            mesh.attribute(id)->SetAttributeValue(draco::AttributeValueIndex(static_cast<std::uint32_t>(v)),
                                                  a.data + v * static_cast<std::size_t>(a.components));
        if (a.quantizationBits > 0) encoder.SetAttributeQuantization(type, a.quantizationBits);
        ids.push_back(id);
    }
    if (sequential) encoder.SetEncodingMethod(draco::MESH_SEQUENTIAL_ENCODING);
    draco::EncoderBuffer out;
    if (const draco::Status status = encoder.EncodeMeshToBuffer(mesh, &out); !status.ok())
        throw std::runtime_error("glTF writer: Draco refused the mesh: " + status.error_msg_string());
    // The counts the accessors declare are what a decoder gives back: the
    // encoder merges and reorders points, and libdraco 1.5's Encoder does
    // not report its counts.
    draco::DecoderBuffer encoded;
    encoded.Init(out.data(), out.size());
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&encoded);
    if (!decoded.ok())
        throw std::runtime_error("glTF writer: Draco's own stream does not decode: " +
                                 decoded.status().error_msg_string());
    const std::size_t points = decoded.value()->num_points(), faces = decoded.value()->num_faces();

    buffer_.resize((buffer_.size() + 3) / 4 * 4, 0);
    const std::size_t offset = buffer_.size();
    buffer_.insert(buffer_.end(), out.data(), out.data() + out.size());
    views_.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", out.size()}});
    Json primitive = {{"attributes", Json::object()}, {"mode", 4}};
    Json ext = {{"bufferView", views_.size() - 1}, {"attributes", Json::object()}};
    for (std::size_t k = 0; k < attributes.size(); ++k) {
        const DracoAttribute& a = attributes[k];
        Json accessor = {{"componentType", kFloat},
                         {"count", points},
                         {"type", a.components == 1 ? "SCALAR" : "VEC" + std::to_string(a.components)}};
        if (a.semantic == "POSITION") {
            std::vector<float> lo(a.data, a.data + 3), hi = lo;
            for (std::size_t v = 0; v < vertexCount; ++v)
                for (std::size_t c = 0; c < 3; ++c) {
                    lo[c] = std::min(lo[c], a.data[v * 3 + c]);
                    hi[c] = std::max(hi[c], a.data[v * 3 + c]);
                }
            accessor["min"] = lo;
            accessor["max"] = hi;
        }
        accessors_.push_back(std::move(accessor));
        primitive["attributes"][a.semantic] = accessors_.size() - 1;
        ext["attributes"][a.semantic] = mesh.attribute(ids[k])->unique_id();
    }
    accessors_.push_back({{"componentType", kUnsignedInt}, {"count", faces * 3}, {"type", "SCALAR"}});
    primitive["indices"] = accessors_.size() - 1;
    primitive["extensions"] = {{"KHR_draco_mesh_compression", ext}};
    for (Json* list : {&extensionsUsed, &extensionsRequired})
        if (std::find(list->begin(), list->end(), "KHR_draco_mesh_compression") == list->end())
            list->push_back("KHR_draco_mesh_compression");
    return primitive.dump();
}

int GltfWriter::pngImage(const std::vector<std::uint8_t>& png) {
    images_.push_back({{"uri", "data:image/png;base64," + base64(png)}});
    return static_cast<int>(images_.size()) - 1;
}

int GltfWriter::image(std::string_view json) { return add(images_, json); }

GltfWriter::Json GltfWriter::document(bool embedBuffer) const {
    Json doc = {{"asset", {{"version", "2.0"}, {"generator", generator}}}};
    const auto put = [&doc](const char* key, const Json& list) {
        if (!list.empty()) doc[key] = list;  // a glTF array, when present, has at least one element
    };
    put("extensionsUsed", extensionsUsed);
    put("extensionsRequired", extensionsRequired);
    doc["scene"] = 0;
    doc["scenes"] = Json::array({{{"nodes", sceneNodes}}});
    put("nodes", nodes);
    put("meshes", meshes);
    put("materials", materials);
    put("textures", textures);
    put("samplers", samplers);
    put("images", images_);
    put("skins", skins);
    put("animations", animations);
    put("accessors", accessors_);
    put("bufferViews", views_);
    if (!buffer_.empty()) {
        Json buffer = {{"byteLength", buffer_.size()}};
        if (embedBuffer) buffer["uri"] = "data:application/octet-stream;base64," + base64(buffer_);
        doc["buffers"] = Json::array({buffer});
    }
    return doc;
}

std::string GltfWriter::text() const { return document(true).dump(1) + "\n"; }

std::string GltfWriter::glb() const {
    std::string json = document(false).dump();
    while (json.size() % 4) json += ' ';
    const std::size_t bin = (buffer_.size() + 3) / 4 * 4;
    std::string out;
    const auto u32 = [&out](std::size_t v) {
        for (int k = 0; k < 4; ++k) out += static_cast<char>((v >> (8 * k)) & 0xFF);
    };
    out += "glTF";
    u32(2);
    u32(12 + 8 + json.size() + (buffer_.empty() ? 0 : 8 + bin));
    u32(json.size());
    out += "JSON" + json;
    if (!buffer_.empty()) {
        u32(bin);
        out += std::string("BIN\0", 4);
        out.append(buffer_.begin(), buffer_.end());
        out.append(bin - buffer_.size(), '\0');
    }
    return out;
}

}  // namespace arcomp
