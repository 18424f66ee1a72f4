#include "graph/io/GltfDraco.hpp"

#include <draco/compression/decode.h>

#include <cstring>

namespace arcomp::gltf {

using nlohmann::json;

namespace {

int componentsOf(const std::string& type) {
    if (type == "SCALAR") return 1;
    if (type == "VEC2") return 2;
    if (type == "VEC3") return 3;
    if (type == "VEC4") return 4;
    return 0;
}

// Appends `count` elements of `components` values of type T to `out`,
// 4-byte aligned, as draco converts them (normalized integers to floats
// when the attribute says so).
template <typename T>
bool appendAttribute(const draco::PointAttribute& attribute, const draco::Mesh& mesh, int components,
                     std::vector<std::uint8_t>& out) {
    const std::size_t start = out.size();
    out.resize(start + std::size_t(mesh.num_points()) * std::size_t(components) * sizeof(T));
    T value[4] = {};
    for (draco::PointIndex p(0); p < mesh.num_points(); ++p) {
        if (!attribute.ConvertValue<T>(attribute.mapped_index(p), static_cast<std::int8_t>(components), value))
            return false;
        std::memcpy(out.data() + start + std::size_t(p.value()) * std::size_t(components) * sizeof(T), value,
                    std::size_t(components) * sizeof(T));
    }
    while (out.size() % 4) out.push_back(0);
    return true;
}

}  // namespace

void decodeDracoPrimitives(GltfDocument& doc) {
    json* meshes = doc.json.contains("meshes") ? &doc.json["meshes"] : nullptr;
    json* accessors = doc.json.contains("accessors") ? &doc.json["accessors"] : nullptr;
    if (!meshes || !meshes->is_array()) return;
    GltfBuffer decoded;
    const std::size_t decodedBuffer = doc.buffers.size();
    json newViews = json::array();
    const std::size_t firstNewView =
        doc.json.contains("bufferViews") && doc.json["bufferViews"].is_array() ? doc.json["bufferViews"].size() : 0;
    // Points accessor `index` at the bytes appended since `start`.
    const auto pointAccessor = [&](std::size_t index, std::size_t start) {
        (*accessors)[index]["bufferView"] = firstNewView + newViews.size();
        (*accessors)[index]["byteOffset"] = 0;
        (*accessors)[index].erase("sparse");
        newViews.push_back(
            {{"buffer", decodedBuffer}, {"byteOffset", start}, {"byteLength", decoded.bytes.size() - start}});
    };
    for (std::size_t m = 0; m < meshes->size(); ++m) {
        json* primitives =
            (*meshes)[m].is_object() && (*meshes)[m].contains("primitives") ? &(*meshes)[m]["primitives"] : nullptr;
        if (!primitives || !primitives->is_array()) continue;
        for (std::size_t p = 0; p < primitives->size(); ++p) {
            json& primitive = (*primitives)[p];
            const json* extensions = member(primitive, "extensions");
            const json* ext = extensions ? member(*extensions, "KHR_draco_mesh_compression") : nullptr;
            if (!ext) continue;
            const std::string where = "/meshes/" + std::to_string(m) + "/primitives/" + std::to_string(p) +
                                      "/extensions/KHR_draco_mesh_compression";
            const ViewBytes stream =
                viewBytes(doc, requiredUnsigned(doc, *ext, "bufferView", where), where + "/bufferView");
            draco::DecoderBuffer input;
            input.Init(reinterpret_cast<const char*>(stream.data), stream.size);
            draco::Decoder decoder;
            auto result = decoder.DecodeMeshFromBuffer(&input);
            if (!result.ok())
                doc.fail(where, "the Draco stream does not decode: " + result.status().error_msg_string());
            const draco::Mesh& mesh = *result.value();

            const json* attributes = member(*ext, "attributes");
            const json* primitiveAttributes = member(primitive, "attributes");
            if (!attributes || !attributes->is_object()) doc.fail(where + "/attributes", "is missing or not an object");
            if (!accessors || !accessors->is_array())
                doc.fail("/accessors", "are missing; the Draco primitive needs them");
            const auto accessorOf = [&](const json* index, const std::string& use) {
                if (!index || !index->is_number_unsigned() || index->get<std::size_t>() >= accessors->size())
                    doc.fail(use, "does not name an accessor");
                return index->get<std::size_t>();
            };
            for (const auto& [semantic, id] : attributes->items()) {
                const std::string use = where + "/attributes/" + semantic;
                const std::size_t index = accessorOf(
                    primitiveAttributes ? member(*primitiveAttributes, semantic.c_str()) : nullptr,
                    "/meshes/" + std::to_string(m) + "/primitives/" + std::to_string(p) + "/attributes/" + semantic);
                if (!id.is_number_unsigned()) doc.fail(use, "is not a Draco attribute id");
                const draco::PointAttribute* attribute = mesh.GetAttributeByUniqueId(id.get<std::uint32_t>());
                if (!attribute)
                    doc.fail(use, "the Draco stream has no attribute " + std::to_string(id.get<std::uint32_t>()));
                const json& accessor = (*accessors)[index];
                const std::string accessorWhere = "/accessors/" + std::to_string(index);
                const std::size_t count = requiredUnsigned(doc, accessor, "count", accessorWhere);
                const json* typeValue = member(accessor, "type");
                const int components =
                    typeValue && typeValue->is_string() ? componentsOf(typeValue->get<std::string>()) : 0;
                if (count != mesh.num_points())
                    doc.fail(accessorWhere + "/count", "is " + std::to_string(count) + ", but the Draco stream of " +
                                                           use + " decodes " + std::to_string(mesh.num_points()) +
                                                           " points");
                if (components != attribute->num_components())
                    doc.fail(accessorWhere + "/type", "has " + std::to_string(components) +
                                                          " components, but the Draco stream of " + use + " decodes " +
                                                          std::to_string(attribute->num_components()));
                const std::size_t start = decoded.bytes.size();
                const std::size_t componentType = unsignedMember(doc, accessor, "componentType", accessorWhere, 0);
                bool converted = false;
                switch (componentType) {
                case 5120: converted = appendAttribute<std::int8_t>(*attribute, mesh, components, decoded.bytes); break;
                case 5121:
                    converted = appendAttribute<std::uint8_t>(*attribute, mesh, components, decoded.bytes);
                    break;
                case 5122:
                    converted = appendAttribute<std::int16_t>(*attribute, mesh, components, decoded.bytes);
                    break;
                case 5123:
                    converted = appendAttribute<std::uint16_t>(*attribute, mesh, components, decoded.bytes);
                    break;
                case 5125:
                    converted = appendAttribute<std::uint32_t>(*attribute, mesh, components, decoded.bytes);
                    break;
                case 5126: converted = appendAttribute<float>(*attribute, mesh, components, decoded.bytes); break;
                default: doc.fail(accessorWhere + "/componentType", "is not a glTF component type");
                }
                if (!converted) doc.fail(use, "the decoded values do not convert to the accessor's component type");
                pointAccessor(index, start);
            }

            const std::string indicesUse =
                "/meshes/" + std::to_string(m) + "/primitives/" + std::to_string(p) + "/indices";
            const std::size_t indices = accessorOf(member(primitive, "indices"), indicesUse);
            const std::size_t count =
                requiredUnsigned(doc, (*accessors)[indices], "count", "/accessors/" + std::to_string(indices));
            if (count != std::size_t(mesh.num_faces()) * 3)
                doc.fail("/accessors/" + std::to_string(indices) + "/count",
                         "is " + std::to_string(count) + ", but the Draco stream of " + where + " decodes " +
                             std::to_string(mesh.num_faces()) + " triangles (" + std::to_string(mesh.num_faces() * 3) +
                             " indices)");
            const std::size_t start = decoded.bytes.size();
            decoded.bytes.resize(start + count * 4);
            for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f)
                for (int k = 0; k < 3; ++k) {
                    const std::uint32_t v = mesh.face(f)[k].value();
                    std::memcpy(decoded.bytes.data() + start + (std::size_t(f.value()) * 3 + std::size_t(k)) * 4, &v,
                                4);
                }
            // Written as unsigned ints whatever the file declared: every index fits.
            (*accessors)[indices]["componentType"] = 5125;
            pointAccessor(indices, start);
        }
    }
    if (newViews.empty()) return;
    json& views = doc.json["bufferViews"];
    if (views.is_null()) views = json::array();
    if (!views.is_array()) doc.fail("/bufferViews", "is not an array");
    for (json& v : newViews) views.push_back(std::move(v));
    doc.buffers.push_back(std::move(decoded));
}

}  // namespace arcomp::gltf
