#include "graph/io/ModelLoader.hpp"
#include "graph/animation/Skinning.hpp"

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

// A clip with node indices of the parsed model, bound to the placed nodes:
// each animated node once, with the pose the file gave it.
ModelAnimation retarget(AnimationClip clip, const ParsedModel& model, const std::vector<NodeId>& ids) {
    ModelAnimation out;
    std::vector<std::uint32_t> slotOf(model.nodes.size(), kNoJoint);
    for (AnimationChannel& c : clip.channels) {
        if (slotOf[c.target] == kNoJoint) {
            slotOf[c.target] = static_cast<std::uint32_t>(out.nodes.size());
            // The parser refuses channels on nodes without TRS.
            out.nodes.push_back({ids[c.target], model.nodes[c.target].trs.value_or(Trs{})});
        }
        c.target = slotOf[c.target];
    }
    out.clip = std::move(clip);
    return out;
}

// Appending cannot fail: by now every index in the parsed model was checked.
NodeId append(ParsedModel& model, Scene& scene, NodeId parent, const std::string& name, const MeshPlacer& placeMesh,
              LoadedModel& loaded) {
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
    // Each skinned node gets a scene skin of its own (its joint matrices undo
    // its own world matrix), added once every joint is placed; its parts name
    // it already. A part is skinned where the parser found nothing against
    // it (checkSkinnedMeshes warned about the rest).
    std::vector<std::size_t> skinnedNodes;
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
        const ModelNode& n = model.nodes[i];
        const NodeId p = n.parent < 0 ? root : ids[static_cast<std::size_t>(n.parent)];
        ids[i] = scene.addTransform(p, n.local, n.name);
        const bool skinnable =
            n.skin >= 0 && model.skins[static_cast<std::size_t>(n.skin)].joints.size() <= kMaxJointsPerDraw;
        const auto sceneSkin = static_cast<std::uint32_t>(scene.skinCount() + skinnedNodes.size());
        bool skinned = false;
        for (const MeshPart& part : n.parts) {
            MeshPart placed{part.geometry + geometryBase, part.material + materialBase};
            if (skinnable && scene.geometry(placed.geometry).hasSkinInfluences()) {
                placed.skin = sceneSkin;
                skinned = true;
            }
            if (placeMesh)
                placeMesh(ids[i], placed);
            else
                scene.addMesh(ids[i], placed);
        }
        if (skinned) skinnedNodes.push_back(i);
    }
    for (const std::size_t i : skinnedNodes) {
        const Skin& skin = model.skins[static_cast<std::size_t>(model.nodes[i].skin)];
        std::vector<NodeId> joints;
        for (const std::uint32_t j : skin.joints) joints.push_back(j == kNoJoint ? kNoNode : ids[j]);
        scene.addSkin(ids[i], joints, skin.inverseBindMatrices);
    }
    for (AnimationClip& clip : model.animations) loaded.animations.push_back(retarget(std::move(clip), model, ids));
    if (!skinnedNodes.empty()) {
        std::vector<NodeId> placedNodes(scene.nodeCount() - root);
        for (std::size_t k = 0; k < placedNodes.size(); ++k) placedNodes[k] = root + static_cast<NodeId>(k);
        fitPosedBounds(scene, placedNodes, loaded.animations);
    }
    const auto placed = [&](std::uint32_t n) { return n == kNoJoint ? kNoNode : ids[n]; };
    for (Skin& skin : model.skins) {
        for (std::uint32_t& j : skin.joints) j = placed(j);
        for (std::uint32_t& u : skin.users) u = placed(u);
        skin.skeleton = placed(skin.skeleton);
        loaded.skins.push_back(std::move(skin));
    }
    return root;
}

}  // namespace

ParsedModel parseModel(const fs::path& file) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec))
        throw ModelError(file.string(), "", fs::exists(file, ec) ? "is not a regular file" : "no such file");
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext == ".gltf" || ext == ".glb" || hasGlbMagic(file)) return parseGltf(file);
    if (ext == ".obj") return parseObj(file);
    throw ModelError(file.string(), "", "unknown model format '" + ext + "'; expected .gltf, .glb or .obj");
}

LoadedModel placeModel(ParsedModel model, Scene& scene, NodeId parent, const std::string& name,
                       const MeshPlacer& placeMesh) {
    LoadedModel out;
    out.root = append(model, scene, parent, name, placeMesh, out);
    out.warnings = std::move(model.warnings);
    out.notDrawn = std::move(model.notDrawn);
    return out;
}

LoadedModel loadModel(const fs::path& file, Scene& scene, NodeId parent, const MeshPlacer& placeMesh) {
    return placeModel(parseModel(file), scene, parent, file.stem().string(), placeMesh);
}

}  // namespace arcomp
