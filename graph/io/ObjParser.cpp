// Wavefront OBJ through tinyobjloader. The material library is read by us,
// not by tinyobjloader, so that its path can be kept inside the model's
// folder like every other URI in content files.

#include "graph/io/ContainedPath.hpp"
#include "graph/io/ModelLoader.hpp"

#include <tiny_obj_loader.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <unordered_map>

namespace arcomp {

namespace fs = std::filesystem;

namespace {

std::string readAll(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// The text of every material library the OBJ names, joined; refusals and
// missing files become warnings, since the geometry is still good.
std::string materialLibraries(const std::string& obj, const fs::path& folder, std::vector<std::string>& warnings) {
    std::string joined;
    std::istringstream lines(obj);
    std::string line;
    int number = 0;
    while (std::getline(lines, line)) {
        ++number;
        if (!line.starts_with("mtllib")) continue;
        std::istringstream words(line.substr(6));
        std::string name;
        while (words >> name) {
            std::string reason;
            const auto path = containedPath(folder, name, reason);
            std::error_code ec;
            if (!path)
                warnings.push_back("line " + std::to_string(number) + ": " + reason + "; materials ignored");
            else if (!fs::is_regular_file(*path, ec))
                warnings.push_back("line " + std::to_string(number) + ": material library '" + name + "' not found");
            else
                joined += readAll(*path) + "\n";
        }
    }
    return joined;
}

}  // namespace

ParsedModel parseObj(const fs::path& file) {
    const std::string name = file.string();
    std::ifstream probe(file, std::ios::binary);
    if (!probe) throw ModelError(name, "", "cannot be read");
    probe.close();
    const std::string text = readAll(file);
    if (text.find('\0') != std::string::npos) throw ModelError(name, "", "is binary, not an OBJ text file");

    ParsedModel out;
    const std::string mtl = materialLibraries(text, file.parent_path(), out.warnings);
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(text, mtl, config)) {
        std::string err = reader.Error();
        while (!err.empty() && err.back() == '\n') err.pop_back();
        throw ModelError(name, "", err.empty() ? "not a readable OBJ file" : err);
    }
    if (!reader.Warning().empty()) out.warnings.push_back(reader.Warning());

    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    const std::size_t positionCount = attrib.vertices.size() / 3;
    const std::size_t normalCount = attrib.normals.size() / 3;
    const std::size_t texcoordCount = attrib.texcoords.size() / 2;

    for (const tinyobj::material_t& src : reader.GetMaterials()) {
        Material m;
        m.name = src.name;
        m.baseColor = glm::vec4(src.diffuse[0], src.diffuse[1], src.diffuse[2], src.dissolve);
        if (src.dissolve < 1.0f) m.alphaMode = AlphaMode::Blend;
        out.materials.push_back(std::move(m));
    }
    const auto defaultMaterial = static_cast<int>(out.materials.size());
    out.materials.push_back(Material{.name = "default"});

    // One geometry per material; OBJ vertices are (position, normal, uv)
    // tuples, shared where a tuple repeats.
    struct Builder {
        Geometry g;
        std::unordered_map<std::uint64_t, std::uint32_t> vertexOf;  // packed tuple to index
        bool anyMissingNormal = false;
    };
    std::map<int, Builder> byMaterial;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        const auto& mesh = shape.mesh;
        std::size_t offset = 0;
        for (std::size_t f = 0; f < mesh.num_face_vertices.size(); ++f) {
            const std::size_t n = mesh.num_face_vertices[f];
            int material = f < mesh.material_ids.size() ? mesh.material_ids[f] : -1;
            if (material < 0 || material >= defaultMaterial) material = defaultMaterial;
            Builder& b = byMaterial[material];
            for (std::size_t k = 0; k < n; ++k) {
                if (offset + k >= mesh.indices.size())
                    throw ModelError(name, "shape '" + shape.name + "'", "face " + std::to_string(f) + " is truncated");
                const tinyobj::index_t idx = mesh.indices[offset + k];
                const auto bad = [&](const char* what, int value, std::size_t count) {
                    throw ModelError(name, "shape '" + shape.name + "' face " + std::to_string(f),
                                     std::string(what) + " " + std::to_string(value) + " is out of range (" +
                                         std::to_string(count) + " defined)");
                };
                if (idx.vertex_index < 0 || static_cast<std::size_t>(idx.vertex_index) >= positionCount)
                    bad("vertex", idx.vertex_index + 1, positionCount);
                if (idx.normal_index >= 0 && static_cast<std::size_t>(idx.normal_index) >= normalCount)
                    bad("normal", idx.normal_index + 1, normalCount);
                if (idx.texcoord_index >= 0 && static_cast<std::size_t>(idx.texcoord_index) >= texcoordCount)
                    bad("texture coordinate", idx.texcoord_index + 1, texcoordCount);
                const std::uint64_t key = (static_cast<std::uint64_t>(idx.vertex_index) << 42) ^
                                          (static_cast<std::uint64_t>(idx.normal_index + 1) << 21) ^
                                          static_cast<std::uint64_t>(idx.texcoord_index + 1);
                auto [it, inserted] = b.vertexOf.try_emplace(key, static_cast<std::uint32_t>(b.g.positions.size()));
                if (inserted) {
                    const auto v = static_cast<std::size_t>(idx.vertex_index);
                    b.g.positions.emplace_back(attrib.vertices[3 * v], attrib.vertices[3 * v + 1],
                                               attrib.vertices[3 * v + 2]);
                    if (idx.normal_index >= 0) {
                        const auto nn = static_cast<std::size_t>(idx.normal_index);
                        b.g.normals.emplace_back(attrib.normals[3 * nn], attrib.normals[3 * nn + 1],
                                                 attrib.normals[3 * nn + 2]);
                    } else {
                        b.anyMissingNormal = true;
                    }
                    if (idx.texcoord_index >= 0) {
                        const auto t = static_cast<std::size_t>(idx.texcoord_index);
                        b.g.texcoords.emplace_back(attrib.texcoords[2 * t], attrib.texcoords[2 * t + 1]);
                    }
                }
                b.g.indices.push_back(it->second);
            }
            offset += n;
        }
    }

    ModelNode node;
    node.name = file.stem().string();
    for (auto& [material, b] : byMaterial) {
        if (b.g.indices.size() < 3) continue;
        for (const glm::vec3& p : b.g.positions)
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                throw ModelError(name, "", "a vertex position is not a finite number");
        if (b.anyMissingNormal) b.g.normals.clear();  // computed by finalize()
        if (b.g.texcoords.size() != b.g.positions.size()) b.g.texcoords.clear();
        b.g.finalize();
        node.parts.push_back({static_cast<std::uint32_t>(out.geometries.size()), static_cast<std::uint32_t>(material)});
        out.geometries.push_back(std::move(b.g));
    }
    if (node.parts.empty()) throw ModelError(name, "", "holds no triangles");
    out.nodes.push_back(std::move(node));
    return out;
}

}  // namespace arcomp
