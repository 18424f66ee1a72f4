// arcomp inspect <scene>: the node tree with counts, and what each drawn
// material uses. Exit 2 with the reason when the scene is rejected.

#include "runtime/station/SceneFile.hpp"
#include "tools/cli/Command.hpp"

#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <set>

namespace arcomp {
namespace {

const char* kindName(NodeKind k) {
    switch (k) {
    case NodeKind::Group: return "group";
    case NodeKind::Transform: return "transform";
    case NodeKind::Mesh: return "mesh";
    case NodeKind::Lod: return "lod";
    case NodeKind::Grouping: return "grouping";
    case NodeKind::SilhouetteRegion: return "silhouette-region";
    case NodeKind::PointCloud: return "point-cloud";
    }
    return "?";
}

// A factor as it reads best in a list: "1", "0.5", "5".
std::string number(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", static_cast<double>(v));
    return text;
}

// A colour or PBR factor, always with a decimal so that a column of them
// reads alike: "0.0", "0.5", "0.25".
std::string decimal(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", static_cast<double>(v));
    std::string s = text;
    if (s.ends_with('0')) s.pop_back();
    return s == "-0.0" ? "0.0" : s;
}

// The glTF features a material draws with, in a fixed order; `used` are the
// geometries drawn with it, which carry the per-vertex ones.
std::vector<std::string> materialFeatures(const Material& m, const std::vector<const Geometry*>& used) {
    std::vector<std::string> f;
    if (m.unlit)
        f.push_back("unlit");
    else
        f.push_back("metallic-roughness (m " + decimal(m.metallic) + ", r " + decimal(m.roughness) + ")");
    if (m.baseColorTexture.present()) f.push_back("base colour texture");
    if (!m.unlit && m.metallicRoughnessTexture.present()) f.push_back("metallic-roughness texture");
    if (!m.unlit && m.normalTexture.present()) f.push_back("normal map (scale " + number(m.normalScale) + ")");
    if (!m.unlit && m.occlusionTexture.present())
        f.push_back("occlusion (strength " + number(m.occlusionStrength) + ")");
    if (m.emissive != glm::vec3(0.0f) || m.emissiveTexture.present()) {
        std::string e =
            "emissive (" + decimal(m.emissive.r) + " " + decimal(m.emissive.g) + " " + decimal(m.emissive.b);
        if (m.emissiveStrength != 1.0f) e += " x" + number(m.emissiveStrength);
        f.push_back(e + (m.emissiveTexture.present() ? ", texture)" : ")"));
    }
    if (m.alphaMode == AlphaMode::Mask) f.push_back("alpha MASK " + number(m.alphaCutoff));
    if (m.alphaMode == AlphaMode::Blend) f.push_back("alpha BLEND");
    if (m.doubleSided) f.push_back("double-sided");
    bool transform = false, secondSet = false;
    for (const TextureRef* t : m.textures()) {
        if (!t->present()) continue;
        transform = transform || t->transform != TextureTransform{};
        secondSet = secondSet || t->texCoord == 1;
    }
    if (transform) f.push_back("texture transform");
    if (secondSet) f.push_back("TEXCOORD_1");
    bool colours = false, fileTangents = false, generatedTangents = false;
    for (const Geometry* g : used) {
        colours = colours || !g->colors.empty();
        fileTangents = fileTangents || (!g->tangents.empty() && !g->tangentsGenerated);
        generatedTangents = generatedTangents || g->tangentsGenerated;
    }
    if (colours) f.push_back("vertex colours");
    if (fileTangents) f.push_back("tangents");
    if (generatedTangents) f.push_back("tangents generated");
    return f;
}

// One line per material a mesh draws with; unused ones (a model's default
// material, say) would only be noise.
void printMaterials(const Scene& scene) {
    std::map<std::uint32_t, std::set<std::uint32_t>> geometriesOf;
    for (NodeId n : scene.order())
        if (scene.kind(n) == NodeKind::Mesh)
            geometriesOf[scene.meshPart(n).material].insert(scene.meshPart(n).geometry);
    for (const auto& [material, geometries] : geometriesOf) {
        std::vector<const Geometry*> used;
        for (std::uint32_t g : geometries) used.push_back(&scene.geometry(g));
        const Material& m = scene.material(material);
        std::cout << "material " << material << " '" << m.name << "':";
        const char* separator = " ";
        for (const std::string& feature : materialFeatures(m, used)) {
            std::cout << separator << feature;
            separator = ", ";
        }
        std::cout << "\n";
    }
}

// A model's animations (index, name, channels, length, interpolations) and
// skins (name, joints), so an integrator can pick the `animation:` to play.
void printAnimations(const SceneFile& file) {
    for (std::size_t i = 0; i < file.animations.size(); ++i) {
        const AnimationClip& clip = file.animations[i].clip;
        std::set<Interpolation> used;
        for (const AnimationChannel& c : clip.channels) used.insert(c.interpolation);
        std::cout << "animation " << i << " '" << clip.name << "': " << clip.channels.size()
                  << (clip.channels.size() == 1 ? " channel, " : " channels, ") << clip.duration() << " s";
        for (Interpolation mode : used) std::cout << ", " << interpolationName(mode);
        std::cout << "\n";
    }
    for (const Skin& skin : file.skins) {
        std::cout << "skin '" << skin.name << "': " << skin.joints.size() << " joints";
        if (skin.joints.size() > kMaxJointsPerDraw)
            std::cout << " (drawn in bind pose: a draw skins at most " << kMaxJointsPerDraw << ")";
        std::cout << "\n";
    }
}

int inspect(const std::string& path) {
    SceneFile file = loadSceneFile(path);
    Scene& scene = file.world.scene;
    scene.update();
    std::size_t meshes = 0, triangles = 0;
    const auto order = scene.order();
    std::vector<int> depth(scene.nodeCount(), 0);
    for (NodeId n : order) {
        if (scene.parent(n) != kNoNode) depth[n] = depth[scene.parent(n)] + 1;
        std::cout << std::string(static_cast<std::size_t>(depth[n]) * 2, ' ') << kindName(scene.kind(n));
        if (!scene.name(n).empty()) std::cout << " '" << scene.name(n) << "'";
        if (scene.kind(n) == NodeKind::Mesh) {
            const MeshPart& part = scene.meshPart(n);
            const std::size_t t = scene.geometry(part.geometry).triangleCount();
            std::cout << ": " << t << " triangles, material '" << scene.material(part.material).name << "'";
            ++meshes;
            triangles += t;
        }
        std::cout << "\n";
    }
    const Sphere b = scene.bound();
    std::cout << "nodes " << scene.nodeCount() << ", meshes " << meshes << ", triangles " << triangles
              << ", geometries " << scene.geometries().size() << ", materials " << scene.materials().size()
              << ", images " << scene.images().size() << "\n";
    if (b.empty())
        std::cout << "bounds: empty\n";
    else
        std::cout << "bounds: centre (" << b.center.x << ", " << b.center.y << ", " << b.center.z << "), radius "
                  << b.radius << "\n";
    printMaterials(scene);
    printAnimations(file);
    if (!file.notDrawn.empty()) {
        std::cout << "not drawn:";
        for (const std::string& e : file.notDrawn) std::cout << ' ' << e;
        std::cout << "\n";
    }
    for (const std::string& w : file.warnings) std::cout << "warning: " << w << "\n";
    return kExitOk;
}

const bool registered =
    registerCommand({"inspect", "Print a scene's node tree with counts and bounds", [](CommandLine& line) {
                         auto path = std::make_shared<std::string>();
                         line.option("scene", *path, "Model or station config").required();
                         return [path] { return inspect(*path); };
                     }});

}  // namespace
}  // namespace arcomp
