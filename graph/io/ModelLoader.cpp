#include "graph/io/ModelLoader.hpp"

#include <algorithm>
#include <fstream>

namespace arcomp {

namespace fs = std::filesystem;

namespace {

bool hasGlbMagic(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    char magic[4] = {};
    in.read(magic, 4);
    return in.gcount() == 4 && std::equal(magic, magic + 4, "glTF");
}

// Appending cannot fail: by now every index in the parsed model was checked.
NodeId append(ParsedModel& model, Scene& scene, NodeId parent, const std::string& name, const MeshPlacer& placeMesh) {
    const auto geometryBase = static_cast<std::uint32_t>(scene.geometries().size());
    const auto materialBase = static_cast<std::uint32_t>(scene.materials().size());
    const auto imageBase = static_cast<int>(scene.images().size());
    for (Image& i : model.images) scene.addImage(std::move(i));
    for (Material& m : model.materials) {
        for (TextureRef* t : m.textures())
            if (t->present()) t->image += imageBase;
        scene.addMaterial(std::move(m));
    }
    for (Geometry& g : model.geometries) scene.addGeometry(std::move(g));
    const NodeId root = scene.addGroup(parent, name);
    std::vector<NodeId> ids(model.nodes.size());
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
        const ModelNode& n = model.nodes[i];
        const NodeId p = n.parent < 0 ? root : ids[static_cast<std::size_t>(n.parent)];
        ids[i] = scene.addTransform(p, n.local, n.name);
        for (const MeshPart& part : n.parts) {
            const MeshPart placed{part.geometry + geometryBase, part.material + materialBase};
            if (placeMesh) placeMesh(ids[i], placed);
            else scene.addMesh(ids[i], placed);
        }
    }
    return root;
}

} // namespace

LoadedModel loadModel(const fs::path& file, Scene& scene, NodeId parent, const MeshPlacer& placeMesh) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec))
        throw ModelError(file.string(), "", fs::exists(file, ec) ? "is not a regular file" : "no such file");
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    ParsedModel model;
    if (ext == ".gltf" || ext == ".glb" || hasGlbMagic(file)) model = parseGltf(file);
    else if (ext == ".obj") model = parseObj(file);
    else throw ModelError(file.string(), "", "unknown model format '" + ext + "'; expected .gltf, .glb or .obj");
    LoadedModel out;
    out.root = append(model, scene, parent, file.stem().string(), placeMesh);
    out.warnings = std::move(model.warnings);
    return out;
}

} // namespace arcomp
