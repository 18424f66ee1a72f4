// arcomp inspect <scene>: the node tree with counts. Exit 2 with the reason
// when the scene is rejected.

#include "runtime/SceneFile.hpp"
#include "tools/arcomp/Command.hpp"

#include <iostream>
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

// A model's animations (index, name, channels, length, interpolations) and
// skins (name, joints), so an integrator can pick the `animation:` to play.
void printAnimations(const SceneFile& file) {
    for (std::size_t i = 0; i < file.animations.size(); ++i) {
        const AnimationClip& clip = file.animations[i].clip;
        std::set<Interpolation> used;
        for (const AnimationChannel& c : clip.channels) used.insert(c.interpolation);
        std::cout << "animation " << i << " '" << clip.name << "': " << clip.channels.size() << " channels, "
                  << clip.duration() << " s";
        for (Interpolation mode : used) std::cout << ", " << interpolationName(mode);
        std::cout << "\n";
    }
    for (const Skin& skin : file.skins)
        std::cout << "skin '" << skin.name << "': " << skin.joints.size() << " joints (drawn in bind pose)\n";
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
    if (b.empty()) std::cout << "bounds: empty\n";
    else std::cout << "bounds: centre (" << b.center.x << ", " << b.center.y << ", " << b.center.z << "), radius " << b.radius << "\n";
    printAnimations(file);
    for (const std::string& w : file.warnings) std::cout << "warning: " << w << "\n";
    return kExitOk;
}

const bool registered = registerCommand({"inspect", "Print a scene's node tree with counts and bounds", [](CommandLine& line) {
                                             auto path = std::make_shared<std::string>();
                                             line.option("scene", *path, "Model or station config").required();
                                             return [path] { return inspect(*path); };
                                         }});

} // namespace
} // namespace arcomp
