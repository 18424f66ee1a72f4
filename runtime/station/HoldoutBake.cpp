#include "runtime/station/HoldoutBake.hpp"
#include "graph/core/JoinText.hpp"

#include "graph/io/SilhouetteFile.hpp"
#include "graph/silhouette/SilhouetteMesh.hpp"

#include <spdlog/spdlog.h>

namespace arcomp {

HoldoutBake bakeHoldouts(World& world, const View& view, const CompositorConfig& config,
                         const std::filesystem::path& cacheFolder, const std::filesystem::path& configFile) {
    Scene& scene = world.scene;
    // Drawn unlit into the mask, with the CG node's own matrix.
    Material white;
    white.name = "holdout";
    white.baseColor = glm::vec4(1.0f);
    white.unlit = true;
    white.doubleSided = true;
    const std::uint32_t material = scene.addMaterial(white);
    const float r = config.holdoutRegionMetres;
    const bool full = config.holdout == HoldoutMesh::Full;

    HoldoutBake bake;
    bake.folder = cacheFolder;
    std::vector<NodeId> meshes;
    for (const NodeId n : scene.order())
        if (scene.kind(n) == NodeKind::Mesh) meshes.push_back(n);
    for (const NodeId n : meshes) {
        // The region is the box of eyes around the camera, in the mesh's own space.
        const glm::mat4 toLocal = glm::inverse(scene.world(n));
        std::vector<glm::vec3> corners;
        for (int i = 0; i < 8; ++i) {
            const glm::vec3 offset((i & 1) ? r : -r, (i & 2) ? r : -r, (i & 4) ? r : -r);
            corners.push_back(glm::vec3(toLocal * glm::vec4(view.eye + offset, 1.0f)));
        }
        if (scene.meshPart(n).skin != kNoSkin) {
            // Posed on the GPU like its CG: nothing to bake or cache.
            world.holdouts.addPosed(scene, n, material);
            ++bake.baked;
            continue;
        }
        const Geometry& g = scene.geometry(scene.meshPart(n).geometry);
        std::vector<ViewRegion> regions;
        if (!full && !movesOverTime(world, n)) regions.push_back(ViewRegion::fromVertices(corners));
        if (bake.folder.empty()) {
            world.holdouts.add(scene, n, bakeSilhouetteMesh(g.positions, g.indices, regions), material);
            ++bake.baked;
            continue;
        }
        const LoadedOrBaked s = loadOrBakeSilhouetteMesh(
            bake.folder / bakeCacheFileName(configFile, scene.name(n), n, ".sil"), g.positions, g.indices, regions);
        world.holdouts.add(scene, n, s.mesh, material);
        if (s.loaded) {
            ++bake.loaded;
        } else {
            ++bake.baked;
            spdlog::info(joinText("holdout of '", scene.name(n), "': ", s.note));
        }
    }
    return bake;
}

}  // namespace arcomp
