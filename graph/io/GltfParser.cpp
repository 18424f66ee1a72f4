// glTF 2.0: arcomp reads the file, its buffers and images and decodes what
// is compressed (GltfDocument); tinygltf parses the rest of the JSON into
// its structs; then everything is checked index by index before it is
// used, since tinygltf leaves ranges, types and the node graph to the
// caller.

#include "graph/io/GltfAnimation.hpp"
#include "graph/io/GltfDocument.hpp"
#include "graph/io/GltfDraco.hpp"
#include "graph/io/GltfImages.hpp"
#include "graph/io/GltfMaterial.hpp"
#include "graph/io/GltfMeshopt.hpp"
#include "graph/io/GltfReader.hpp"
#include "graph/io/ModelLoader.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

namespace arcomp {

using namespace gltf;

namespace {

// The extensions arcomp draws: a file may require them.
const std::set<std::string> kSupportedRequired{
    "KHR_materials_unlit",        "KHR_mesh_quantization",   "KHR_texture_transform", "KHR_materials_emissive_strength",
    "KHR_draco_mesh_compression", "EXT_meshopt_compression", "EXT_texture_webp"};

// What a user can do about a required extension arcomp cannot draw.
std::string remedy(const std::string& extension) {
    if (extension == "KHR_texture_basisu")
        return "Debian 12 has no KTX2 decoder; re-export with PNG, JPEG or WebP textures (gltfpack without -tc)";
    std::string drawn;
    for (const std::string& e : kSupportedRequired) drawn += (drawn.empty() ? "" : ", ") + e;
    return "re-export without it; arcomp draws " + drawn;
}

// What is drawn in place of a used extension arcomp leaves out.
std::string drawnInstead(const std::string& extension) {
    if (extension == "KHR_texture_basisu") return "its textures are drawn from their fallback images";
    return "the model is drawn without it";
}

// Refuses the first required extension arcomp cannot draw; lists, and warns
// once for, each used one it leaves out.
void checkExtensions(const nlohmann::json& doc, const std::string& name, ParsedModel& out) {
    if (const auto r = doc.find("extensionsRequired"); r != doc.end()) {
        if (!r->is_array()) throw ModelError(name, "/extensionsRequired", "is not an array of extension names");
        for (std::size_t i = 0; i < r->size(); ++i) {
            if (!(*r)[i].is_string()) throw ModelError(name, ptr("extensionsRequired", i), "is not an extension name");
            const std::string extension = (*r)[i];
            if (!kSupportedRequired.contains(extension))
                throw ModelError(name, ptr("extensionsRequired", i),
                                 "requires extension " + extension +
                                     ", which arcomp cannot draw: " + remedy(extension));
        }
    }
    if (const auto u = doc.find("extensionsUsed"); u != doc.end() && u->is_array())
        for (const auto& used : *u)
            if (used.is_string() && !kSupportedRequired.contains(used.get<std::string>())) {
                const std::string extension = used.get<std::string>();
                out.notDrawn.push_back(extension);
                out.warnings.push_back("uses extension " + extension +
                                       ", which arcomp does not draw: " + drawnInstead(extension));
            }
}

// What tinygltf 2.7 would refuse while parsing, set aside so that arcomp's
// own checks see it: tinygltf gets the document without buffers and images
// (arcomp read and decoded them), whole floats as integers, with a WebP
// texture's source in place of its fallback, an unknown accessor type as
// SCALAR and indices without a buffer view left out; parseGltf puts the
// last two back.
struct SetAside {
    nlohmann::json tinygltfJson;
    std::vector<std::size_t> unknownTypes;            // accessors
    std::vector<std::array<std::size_t, 3>> indices;  // mesh, primitive, accessor
};

// JSON has one number type, and the validator takes 4.0 where the schema
// asks for an integer; tinygltf 2.7 does not. Every whole float becomes an
// integer, which tinygltf also takes wherever it expects a number.
void wholeFloatsAsIntegers(nlohmann::json& value) {
    if (value.is_structured()) {
        for (auto& child : value) wholeFloatsAsIntegers(child);
    } else if (value.is_number_float()) {
        const double d = value.get<double>();
        if (std::abs(d) <= 9007199254740992.0 && d == std::trunc(d)) value = static_cast<std::int64_t>(d);
    }
}

SetAside setAside(const GltfDocument& doc) {
    SetAside out{nlohmann::json::object(), {}, {}};
    nlohmann::json& j = out.tinygltfJson;
    // Copied member by member: the buffers' and images' data URIs can be
    // most of the document.
    for (const auto& [key, value] : doc.json.items())
        if (key != "buffers" && key != "images") j[key] = value;
    wholeFloatsAsIntegers(j);
    if (auto t = j.find("textures"); t != j.end() && t->is_array())
        for (auto& texture : *t)
            if (const nlohmann::json* ext = member(texture, "extensions"))
                if (const nlohmann::json* webp = member(*ext, "EXT_texture_webp"))
                    if (const nlohmann::json* source = member(*webp, "source")) texture["source"] = *source;
    const std::set<std::string> types{"SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4"};
    const auto a = j.find("accessors");
    const bool haveAccessors = a != j.end() && a->is_array();
    if (haveAccessors)
        for (std::size_t i = 0; i < a->size(); ++i) {
            nlohmann::json& accessor = (*a)[i];
            const nlohmann::json* type = member(accessor, "type");
            if (type && type->is_string() && !types.contains(type->get<std::string>())) {
                accessor["type"] = "SCALAR";
                out.unknownTypes.push_back(i);
            }
        }
    if (auto m = j.find("meshes"); haveAccessors && m != j.end() && m->is_array())
        for (std::size_t mesh = 0; mesh < m->size(); ++mesh) {
            nlohmann::json* primitives =
                (*m)[mesh].is_object() && (*m)[mesh].contains("primitives") ? &(*m)[mesh]["primitives"] : nullptr;
            if (!primitives || !primitives->is_array()) continue;
            for (std::size_t p = 0; p < primitives->size(); ++p) {
                const nlohmann::json* index = member((*primitives)[p], "indices");
                if (!index || !index->is_number_unsigned() || index->get<std::size_t>() >= a->size()) continue;
                if (member((*a)[index->get<std::size_t>()], "bufferView")) continue;
                out.indices.push_back({mesh, p, index->get<std::size_t>()});
                (*primitives)[p].erase("indices");
            }
        }
    return out;
}

bool refuseExists(const std::string&, void*) { return false; }
std::string identityExpand(const std::string& path, void*) { return path; }
bool refuseRead(std::vector<unsigned char>*, std::string* err, const std::string& path, void*) {
    if (err) *err += "tinygltf may not read files (" + path + "); arcomp reads them\n";
    return false;
}
bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "writing is not allowed\n";
    return false;
}

// What a skinned node's primitives must agree with its skin on: every joint
// that carries weight is one of the skin's (glTF 2.0, 3.7.3.3), or the file
// is refused. What arcomp cannot skin is drawn in its bind pose, and said:
// primitives without JOINTS_0 and WEIGHTS_0, and skins with more joints than
// one draw takes (kMaxJointsPerDraw). placeModel reads the same conditions.
void checkSkinnedMeshes(const tinygltf::Model& model, const std::vector<int>& parsedOf,
                        const std::vector<std::string>& geometrySource, const GltfReader& reader, ParsedModel& out) {
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        const int parsed = parsedOf[n];
        if (parsed < 0) continue;
        const ModelNode& node = out.nodes[static_cast<std::size_t>(parsed)];
        if (node.skin < 0 || node.parts.empty()) continue;
        const Skin& skin = out.skins[static_cast<std::size_t>(node.skin)];
        const std::string skinLabel = "skin " + std::to_string(node.skin) + " '" + skin.name + "'";
        if (skin.joints.size() > kMaxJointsPerDraw) {
            out.warnings.push_back(ptr("nodes", n) + ": " + skinLabel + " has " + std::to_string(skin.joints.size()) +
                                   " joints, more than the " + std::to_string(kMaxJointsPerDraw) +
                                   " arcomp skins in one draw; drawn in its bind pose");
            continue;
        }
        for (const MeshPart& part : node.parts) {
            const Geometry& g = out.geometries[part.geometry];
            const std::string& source = geometrySource[part.geometry];
            if (!g.hasSkinInfluences()) {
                out.warnings.push_back(source + ": skinned by " + skinLabel + " (" + ptr("nodes", n) +
                                       ") but has no skin influences to pose it; drawn in its bind pose");
                continue;
            }
            for (std::size_t v = 0; v < g.joints.size(); ++v)
                for (int k = 0; k < 4; ++k)
                    if (g.weights[v][k] > 0.0f && g.joints[v][k] >= skin.joints.size())
                        reader.fail(source + "/attributes/JOINTS_0",
                                    "vertex " + std::to_string(v) + " uses joint " + std::to_string(g.joints[v][k]) +
                                        ", but " + skinLabel + " of " + ptr("nodes", n) + " has " +
                                        std::to_string(skin.joints.size()) + " joints");
        }
    }
}

glm::mat4 nodeMatrix(const tinygltf::Node& node, std::size_t index, const GltfReader& reader) {
    const std::string where = ptr("nodes", index);
    auto finite = [&](const std::vector<double>& v, const char* field) {
        for (double d : v)
            if (!std::isfinite(d)) reader.fail(where + "/" + field, "holds a value that is not finite");
    };
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) reader.fail(where + "/matrix", "must have 16 numbers");
        finite(node.matrix, "matrix");
        glm::mat4 m;
        for (int i = 0; i < 16; ++i)
            glm::value_ptr(m)[i] = static_cast<float>(node.matrix[static_cast<std::size_t>(i)]);
        return m;
    }
    glm::mat4 m(1.0f);
    if (!node.translation.empty()) {
        if (node.translation.size() != 3) reader.fail(where + "/translation", "must have 3 numbers");
        finite(node.translation, "translation");
        m = glm::translate(m, glm::vec3(node.translation[0], node.translation[1], node.translation[2]));
    }
    if (!node.rotation.empty()) {
        if (node.rotation.size() != 4) reader.fail(where + "/rotation", "must have 4 numbers");
        finite(node.rotation, "rotation");
        glm::quat q(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                    static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2]));
        const float len = glm::length(q);
        if (len > 0.0f) m *= glm::mat4_cast(q / len);
    }
    if (!node.scale.empty()) {
        if (node.scale.size() != 3) reader.fail(where + "/scale", "must have 3 numbers");
        finite(node.scale, "scale");
        m = glm::scale(m, glm::vec3(node.scale[0], node.scale[1], node.scale[2]));
    }
    return m;
}

// Triangle lists from the three triangle modes.
std::vector<std::uint32_t> triangulate(int mode, std::vector<std::uint32_t> idx) {
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        idx.resize(idx.size() - idx.size() % 3);
        return idx;
    }
    std::vector<std::uint32_t> out;
    for (std::size_t i = 2; i < idx.size(); ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            // Every other triangle of a strip is flipped to keep the winding.
            if (i % 2 == 0)
                out.insert(out.end(), {idx[i - 2], idx[i - 1], idx[i]});
            else
                out.insert(out.end(), {idx[i - 1], idx[i - 2], idx[i]});
        } else {
            out.insert(out.end(), {idx[0], idx[i - 1], idx[i]});
        }
    }
    return out;
}

}  // namespace

ParsedModel parseGltf(const fs::path& file) {
    const std::string name = file.string();
    GltfDocument doc = readGltfDocument(file);
    ParsedModel out;
    checkExtensions(doc.json, name, out);
    decodeMeshoptViews(doc);
    decodeDracoPrimitives(doc);
    std::vector<std::string> imageWarnings;
    out.images = readGltfImages(doc, imageWarnings);

    SetAside aside = setAside(doc);
    const std::string text = aside.tinygltfJson.dump();
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({&refuseExists, &identityExpand, &refuseRead, &refuseWrite, nullptr});
    tinygltf::Model model;
    std::string err, warn;
    bool ok = false;
    try {
        ok = loader.LoadASCIIFromString(&model, &err, &warn, text.c_str(), static_cast<unsigned>(text.size()),
                                        doc.folder.string());
    } catch (const std::exception& e) {
        throw ModelError(name, "", std::string("malformed glTF, the loader stopped: ") + e.what());
    }
    if (!ok) {
        while (!err.empty() && err.back() == '\n') err.pop_back();
        throw ModelError(name, "", err.empty() ? "not a readable glTF file" : err);
    }
    for (std::size_t start = 0; start < warn.size();) {
        const auto end = warn.find('\n', start);
        const std::string line = warn.substr(start, end - start);
        if (!line.empty()) out.warnings.push_back(line);
        if (end == std::string::npos) break;
        start = end + 1;
    }
    out.warnings.insert(out.warnings.end(), imageWarnings.begin(), imageWarnings.end());

    std::vector<std::string> absent;
    model.buffers.resize(doc.buffers.size());
    for (std::size_t i = 0; i < doc.buffers.size(); ++i) {
        model.buffers[i].data = std::move(doc.buffers[i].bytes);
        absent.push_back(std::move(doc.buffers[i].absent));
    }
    for (const std::size_t i : aside.unknownTypes) model.accessors[i].type = -1;
    for (const auto& [mesh, primitive, accessor] : aside.indices)
        model.meshes[mesh].primitives[primitive].indices = static_cast<int>(accessor);

    GltfReader reader(file, model, std::move(absent));
    for (std::size_t i = 0; i < model.bufferViews.size(); ++i) reader.checkView(i);
    for (std::size_t i = 0; i < model.accessors.size(); ++i) reader.checkAccessorLayout(i);

    // Materials; a default one serves primitives that name none. Every
    // texture and sampler is checked, used or not, like the meshes below.
    out.materials = readMaterials(model, out.images, reader, out.warnings);
    const auto defaultMaterial = static_cast<std::uint32_t>(out.materials.size());
    out.materials.push_back(Material{.name = "default"});

    // The node graph must be a forest: every child index valid, no node with
    // two parents, no cycle.
    const std::size_t nodeCount = model.nodes.size();
    std::vector<int> parentOf(nodeCount, -1);
    for (std::size_t i = 0; i < nodeCount; ++i) {
        for (std::size_t c = 0; c < model.nodes[i].children.size(); ++c) {
            const int child = model.nodes[i].children[c];
            const std::string where = ptr("nodes", i) + "/children/" + std::to_string(c);
            if (child < 0 || static_cast<std::size_t>(child) >= nodeCount)
                reader.fail(where, "node " + std::to_string(child) + " does not exist");
            if (static_cast<std::size_t>(child) == i) reader.fail(where, "node is its own child");
            if (parentOf[static_cast<std::size_t>(child)] >= 0)
                reader.fail(where, "node " + std::to_string(child) + " already has parent " +
                                       std::to_string(parentOf[static_cast<std::size_t>(child)]));
            parentOf[static_cast<std::size_t>(child)] = static_cast<int>(i);
        }
    }
    for (std::size_t i = 0; i < nodeCount; ++i) {
        // With one parent each, a cycle is a walk upwards that never ends.
        std::size_t steps = 0;
        for (int p = parentOf[i]; p >= 0; p = parentOf[static_cast<std::size_t>(p)])
            if (++steps > nodeCount) reader.fail(ptr("nodes", i), "is part of a cycle in the node graph");
    }

    std::vector<int> roots;
    if (!model.scenes.empty()) {
        int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : 0;
        if (static_cast<std::size_t>(sceneIndex) >= model.scenes.size())
            reader.fail("/scene", "scene " + std::to_string(sceneIndex) + " does not exist");
        const auto& nodes = model.scenes[static_cast<std::size_t>(sceneIndex)].nodes;
        for (std::size_t k = 0; k < nodes.size(); ++k) {
            const std::string where =
                ptr("scenes", static_cast<std::size_t>(sceneIndex)) + "/nodes/" + std::to_string(k);
            if (nodes[k] < 0 || static_cast<std::size_t>(nodes[k]) >= nodeCount)
                reader.fail(where, "node " + std::to_string(nodes[k]) + " does not exist");
            if (parentOf[static_cast<std::size_t>(nodes[k])] >= 0)
                reader.fail(where, "node " + std::to_string(nodes[k]) + " is not a root node");
            roots.push_back(nodes[k]);
        }
    } else {
        for (std::size_t i = 0; i < nodeCount; ++i)
            if (parentOf[i] < 0) roots.push_back(static_cast<int>(i));
    }

    // A texture whose TEXCOORD_n a primitive lacks cannot be drawn on it; the
    // primitive gets a copy of its material without such slots, one copy
    // per material and set of slots, and the other primitives keep theirs.
    std::map<std::pair<std::uint32_t, unsigned>, std::uint32_t> withoutSlots;
    auto drawableMaterial = [&](std::uint32_t material, const Geometry& g, const std::string& where) {
        const Material& m = out.materials[material];
        const auto slots = m.textures();
        unsigned dropped = 0;
        for (std::size_t k = 0; k < slots.size(); ++k) {
            const bool lacks = slots[k]->texCoord == 1 ? g.texcoords1.empty() : g.texcoords.empty();
            if (!slots[k]->present() || !lacks) continue;
            dropped |= 1u << k;
            out.warnings.push_back(where + ": " + materialLabel(material, m.name) + " maps its " + kSlotNames[k] +
                                   " texture with TEXCOORD_" + std::to_string(slots[k]->texCoord) +
                                   ", which the primitive lacks; drawn without that texture");
        }
        if (dropped == 0) return material;
        const auto [at, added] =
            withoutSlots.try_emplace({material, dropped}, static_cast<std::uint32_t>(out.materials.size()));
        if (added) {
            Material copy = m;
            const auto copySlots = copy.textures();
            for (std::size_t k = 0; k < copySlots.size(); ++k)
                if (dropped & (1u << k)) *copySlots[k] = TextureRef{};
            out.materials.push_back(std::move(copy));
        }
        return at->second;
    };

    // JOINTS_0 and WEIGHTS_0 (glTF 2.0, 3.7.3.3): joints unsigned bytes or
    // shorts; weights floats or normalized unsigned bytes or shorts, summing
    // to 1. A joint with no weight is set to 0, so that it indexes inside any
    // skin; the joints with weight are checked against the node's skin once
    // nodes are read. Weights that do not sum to 1 are rescaled (quantized
    // ones rarely do exactly); only a sum far from 1 is worth a warning. A
    // vertex with no weight at all has no pose: the validator passes such
    // files (placeholder accessors of zeros), so the primitive is drawn
    // unskinned rather than refused.
    auto readSkinInfluences = [&](const tinygltf::Primitive& prim, const std::string& where, std::size_t vertexCount,
                                  Geometry& g) {
        const auto joints = prim.attributes.find("JOINTS_0");
        const auto weights = prim.attributes.find("WEIGHTS_0");
        for (const char* second : {"JOINTS_1", "WEIGHTS_1"})
            if (prim.attributes.count(second))
                out.warnings.push_back(where + "/attributes/" + second +
                                       ": ignored; arcomp skins with the first four influences (JOINTS_0, WEIGHTS_0)");
        if (joints == prim.attributes.end() && weights == prim.attributes.end()) return;
        if (joints == prim.attributes.end() || weights == prim.attributes.end())
            reader.fail(where + "/attributes",
                        std::string("has ") + (joints == prim.attributes.end() ? "WEIGHTS_0" : "JOINTS_0") +
                            " without " + (joints == prim.attributes.end() ? "JOINTS_0" : "WEIGHTS_0"));
        const std::string jointsUse = where + "/attributes/JOINTS_0", weightsUse = where + "/attributes/WEIGHTS_0";
        const auto jointsIndex = static_cast<std::size_t>(joints->second),
                   weightsIndex = static_cast<std::size_t>(weights->second);
        for (const auto& [index, use] : {std::pair{jointsIndex, jointsUse}, std::pair{weightsIndex, weightsUse}})
            if (reader.count(index, use) != vertexCount)
                reader.fail(use, "has " + std::to_string(reader.count(index, use)) + " elements, POSITION has " +
                                     std::to_string(vertexCount));
        if (reader.describe(jointsIndex, jointsUse).normalized)
            reader.fail(ptr("accessors", jointsIndex, "normalized"),
                        "is true; joint indices are not normalized (used by " + jointsUse + ")");
        const tinygltf::Accessor& w = reader.describe(weightsIndex, weightsUse);
        if (w.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !w.normalized)
            reader.fail(ptr("accessors", weightsIndex, "normalized"),
                        "is false; unsigned byte or short weights must be normalized (used by " + weightsUse + ")");
        const auto j =
            reader.readFloats(jointsIndex, jointsUse, TINYGLTF_TYPE_VEC4,
                              {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT});
        const auto v = reader.readFloats(weightsIndex, weightsUse, TINYGLTF_TYPE_VEC4,
                                         {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                          TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT});
        g.joints.resize(vertexCount);
        g.weights.resize(vertexCount);
        std::size_t farOff = 0, firstFarOff = 0, weightless = 0, firstWeightless = 0;
        for (std::size_t i = 0; i < vertexCount; ++i) {
            glm::vec4 weight(v[i * 4], v[i * 4 + 1], v[i * 4 + 2], v[i * 4 + 3]);
            if (glm::any(glm::lessThan(weight, glm::vec4(0.0f))))
                reader.fail(weightsUse, "vertex " + std::to_string(i) + " has a negative weight");
            const float sum = weight.x + weight.y + weight.z + weight.w;
            if (!(sum > 0.0f)) {
                if (weightless++ == 0) firstWeightless = i;
                continue;
            }
            if (std::abs(sum - 1.0f) > 0.01f && farOff++ == 0) firstFarOff = i;
            weight /= sum;
            glm::u16vec4 joint(0);
            for (int k = 0; k < 4; ++k)
                if (weight[k] > 0.0f) joint[k] = static_cast<std::uint16_t>(j[i * 4 + static_cast<std::size_t>(k)]);
            g.joints[i] = joint;
            g.weights[i] = weight;
        }
        if (weightless > 0) {
            out.warnings.push_back(weightsUse + ": " + std::to_string(weightless) + " vertices (the first vertex " +
                                   std::to_string(firstWeightless) +
                                   ") have no weight on any joint; the primitive is not skinned");
            g.joints.clear();
            g.weights.clear();
            return;
        }
        if (farOff > 0)
            out.warnings.push_back(weightsUse + ": the weights of " + std::to_string(farOff) +
                                   " vertices (the first vertex " + std::to_string(firstFarOff) +
                                   ") do not sum to 1; rescaled so they do");
    };

    // Each (mesh, primitive) becomes one geometry, shared by every node that
    // uses the mesh. Every mesh is checked, used or not: a file that holds
    // unsafe data anywhere is not one to trust.
    std::vector<std::string> geometrySource;  // per geometry: its primitive's JSON pointer
    auto primitiveParts = [&](int meshIndex) {
        std::vector<MeshPart> parts;
        const tinygltf::Mesh& mesh = model.meshes[static_cast<std::size_t>(meshIndex)];
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const tinygltf::Primitive& prim = mesh.primitives[p];
            const std::string where =
                ptr("meshes", static_cast<std::size_t>(meshIndex)) + "/primitives/" + std::to_string(p);
            std::uint32_t material = defaultMaterial;
            if (prim.material >= 0) {
                if (static_cast<std::size_t>(prim.material) >= model.materials.size())
                    reader.fail(where + "/material", "material " + std::to_string(prim.material) + " does not exist");
                material = static_cast<std::uint32_t>(prim.material);
            }
            const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
            if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
                mode != TINYGLTF_MODE_TRIANGLE_FAN) {
                out.warnings.push_back(where + "/mode: mode " + std::to_string(mode) + " is not triangles; skipped");
                continue;
            }
            const auto position = prim.attributes.find("POSITION");
            if (position == prim.attributes.end()) {
                out.warnings.push_back(where + "/attributes: no POSITION; skipped");
                continue;
            }
            const auto attributePointer = [&](const std::string& attribute) {
                return where + "/attributes/" + attribute;
            };
            using CT = std::vector<int>;
            const CT floatOrQuantized{TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE,
                                      TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT,
                                      TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};
            const bool quantized = std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(),
                                             "KHR_mesh_quantization") != model.extensionsUsed.end();
            const CT positionTypes = quantized ? floatOrQuantized : CT{TINYGLTF_COMPONENT_TYPE_FLOAT};
            Geometry g;
            const auto positionIndex = static_cast<std::size_t>(position->second);
            const std::vector<float> pos =
                reader.readFloats(positionIndex, attributePointer("POSITION"), TINYGLTF_TYPE_VEC3, positionTypes);
            const std::size_t vertexCount = pos.size() / 3;
            g.positions.resize(vertexCount);
            std::memcpy(g.positions.data(), pos.data(), pos.size() * sizeof(float));
            auto sameCount = [&](const std::string& attribute, std::size_t index) {
                if (reader.count(index, attributePointer(attribute)) != vertexCount)
                    reader.fail(attributePointer(attribute),
                                "has " + std::to_string(reader.count(index, attributePointer(attribute))) +
                                    " elements, POSITION has " + std::to_string(vertexCount));
            };
            if (auto n = prim.attributes.find("NORMAL"); n != prim.attributes.end()) {
                sameCount("NORMAL", static_cast<std::size_t>(n->second));
                const CT normalTypes = quantized ? CT{TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE,
                                                      TINYGLTF_COMPONENT_TYPE_SHORT}
                                                 : CT{TINYGLTF_COMPONENT_TYPE_FLOAT};
                const auto v = reader.readFloats(static_cast<std::size_t>(n->second), attributePointer("NORMAL"),
                                                 TINYGLTF_TYPE_VEC3, normalTypes);
                g.normals.resize(vertexCount);
                for (std::size_t i = 0; i < vertexCount; ++i) {
                    const glm::vec3 nrm(v[i * 3], v[i * 3 + 1], v[i * 3 + 2]);
                    const float len = glm::length(nrm);
                    g.normals[i] = len > 0.0f ? nrm / len : glm::vec3(0, 0, 1);
                }
            }
            const auto readTexcoords = [&](const char* attribute, std::vector<glm::vec2>& to) {
                const auto t = prim.attributes.find(attribute);
                if (t == prim.attributes.end()) return;
                sameCount(attribute, static_cast<std::size_t>(t->second));
                const auto v = reader.readFloats(static_cast<std::size_t>(t->second), attributePointer(attribute),
                                                 TINYGLTF_TYPE_VEC2, floatOrQuantized);
                to.resize(vertexCount);
                std::memcpy(to.data(), v.data(), v.size() * sizeof(float));
            };
            readTexcoords("TEXCOORD_0", g.texcoords);
            readTexcoords("TEXCOORD_1", g.texcoords1);
            if (auto c = prim.attributes.find("COLOR_0"); c != prim.attributes.end()) {
                const auto index = static_cast<std::size_t>(c->second);
                const std::string use = attributePointer("COLOR_0");
                sameCount("COLOR_0", index);
                // The spec's forms: VEC3 or VEC4, of floats or of normalized
                // unsigned bytes or shorts.
                const tinygltf::Accessor& a = reader.describe(index, use);
                if (a.type != TINYGLTF_TYPE_VEC3 && a.type != TINYGLTF_TYPE_VEC4)
                    reader.fail(ptr("accessors", index, "type"), std::string("is ") + typeName(a.type) +
                                                                     ", expected VEC3 or VEC4 (used by " + use + ")");
                if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !a.normalized &&
                    (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                     a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT))
                    reader.fail(ptr("accessors", index, "normalized"),
                                "is false; unsigned byte or short colours must be normalized (used by " + use + ")");
                const auto v =
                    reader.readFloats(index, use, a.type,
                                      CT{TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                         TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT});
                const std::size_t n = a.type == TINYGLTF_TYPE_VEC4 ? 4 : 3;
                g.colors.resize(vertexCount);
                // Float colours outside [0, 1] break the spec, not the drawing:
                // clamped, as a normalized integer would have been.
                for (std::size_t i = 0; i < vertexCount; ++i)
                    g.colors[i] = glm::clamp(
                        glm::vec4(v[i * n], v[i * n + 1], v[i * n + 2], n == 4 ? v[i * n + 3] : 1.0f), 0.0f, 1.0f);
            }
            if (auto t = prim.attributes.find("TANGENT"); t != prim.attributes.end()) {
                const auto index = static_cast<std::size_t>(t->second);
                sameCount("TANGENT", index);
                const CT tangentTypes = quantized ? CT{TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE,
                                                       TINYGLTF_COMPONENT_TYPE_SHORT}
                                                  : CT{TINYGLTF_COMPONENT_TYPE_FLOAT};
                const auto v = reader.readFloats(index, attributePointer("TANGENT"), TINYGLTF_TYPE_VEC4, tangentTypes);
                if (g.normals.empty()) {
                    // The spec: without normals, flat ones are computed and the
                    // tangents ignored; they could not match computed normals.
                    out.warnings.push_back(attributePointer("TANGENT") + ": ignored, the primitive has no NORMAL");
                } else {
                    // Like the normals: unit length, and w a sign, whatever the
                    // file's rounding.
                    g.tangents.resize(vertexCount);
                    for (std::size_t i = 0; i < vertexCount; ++i) {
                        const glm::vec3 xyz(v[i * 4], v[i * 4 + 1], v[i * 4 + 2]);
                        const float len = glm::length(xyz);
                        g.tangents[i] =
                            glm::vec4(len > 0.0f ? xyz / len : glm::vec3(1, 0, 0), v[i * 4 + 3] < 0.0f ? -1.0f : 1.0f);
                    }
                }
            }
            readSkinInfluences(prim, where, vertexCount, g);
            std::vector<std::uint32_t> indices;
            if (prim.indices >= 0) {
                indices = reader.readIndices(static_cast<std::size_t>(prim.indices), where + "/indices", vertexCount);
            } else {
                indices.resize(vertexCount);
                for (std::size_t i = 0; i < vertexCount; ++i) indices[i] = static_cast<std::uint32_t>(i);
            }
            g.indices = triangulate(mode, std::move(indices));
            g.finalize();
            material = drawableMaterial(material, g, where);
            if (const TextureRef& normalMap = out.materials[material].normalTexture;
                normalMap.present() && g.tangents.empty()) {
                g.tangents = computeTangents(g.positions, g.normals,
                                             normalMap.texCoord == 1 ? g.texcoords1 : g.texcoords, g.indices);
                g.tangentsGenerated = true;
            }
            const auto id = static_cast<std::uint32_t>(out.geometries.size());
            out.geometries.push_back(std::move(g));
            geometrySource.push_back(where);
            parts.push_back({id, material});
        }
        return parts;
    };

    std::vector<std::vector<MeshPart>> partsOfMesh;
    for (std::size_t m = 0; m < model.meshes.size(); ++m) partsOfMesh.push_back(primitiveParts(static_cast<int>(m)));

    // Parents before children, as ParsedModel promises.
    std::vector<int> parsedOf(nodeCount, -1);  // glTF node -> its index in out.nodes
    std::vector<std::pair<int, int>> stack;    // glTF node, parsed parent
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, -1});
    while (!stack.empty()) {
        const auto [index, parent] = stack.back();
        stack.pop_back();
        const auto i = static_cast<std::size_t>(index);
        const tinygltf::Node& src = model.nodes[i];
        ModelNode node;
        node.parent = parent;
        node.local = nodeMatrix(src, i, reader);
        node.trs = authoredTrs(src);
        node.name = src.name;
        if (src.mesh >= 0) {
            if (static_cast<std::size_t>(src.mesh) >= partsOfMesh.size())
                reader.fail(ptr("nodes", i, "mesh"), "mesh " + std::to_string(src.mesh) + " does not exist");
            node.parts = partsOfMesh[static_cast<std::size_t>(src.mesh)];
        }
        const int self = static_cast<int>(out.nodes.size());
        parsedOf[i] = self;
        out.nodes.push_back(std::move(node));
        for (auto c = src.children.rbegin(); c != src.children.rend(); ++c) stack.push_back({*c, self});
    }
    readGltfAnimation(model, reader, parsedOf, out);
    checkSkinnedMeshes(model, parsedOf, geometrySource, reader, out);
    return out;
}

}  // namespace arcomp
