#include "graph/io/GltfWriter.hpp"

#include "graph/io/Base64.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

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

int GltfWriter::pngImage(const std::vector<std::uint8_t>& png) {
    images_.push_back({{"uri", "data:image/png;base64," + base64(png)}});
    return static_cast<int>(images_.size()) - 1;
}

int GltfWriter::image(std::string_view json) { return add(images_, json); }

std::string GltfWriter::text() const {
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
    if (!buffer_.empty())
        doc["buffers"] = Json::array(
            {{{"byteLength", buffer_.size()}, {"uri", "data:application/octet-stream;base64," + base64(buffer_)}}});
    return doc.dump(1) + "\n";
}

}  // namespace arcomp
