#include "runtime/station/SceneFile.hpp"
#include "graph/core/JoinText.hpp"

#include "graph/io/LodFile.hpp"
#include "graph/io/ModelLoader.hpp"
#include "graph/lod/LodLevels.hpp"
#include "runtime/station/GroupingSetup.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <spdlog/spdlog.h>

#include <algorithm>

namespace arcomp {

namespace fs = std::filesystem;

View cameraView(const CameraConfig& c) {
    if (c.calibrated) return c.calibrated->view(c.size, c.near, c.far);
    return View::lookAt(c.eye, c.target, c.up, c.fovyDegrees, c.size, c.near, c.far);
}

namespace {

LodNode lodSettings(const ObjectConfig& o) {
    LodNode node;
    node.policy = o.lodPolicy;
    node.levelCount = static_cast<std::uint8_t>(o.lodRatios.size());
    std::copy(o.lodThresholds.begin(), o.lodThresholds.end(), node.thresholds.begin());
    node.fadeSeconds = o.lodFadeSeconds;
    return node;
}

}  // namespace

BakeTally buildScene(const StationConfig& cfg, World& world, std::vector<std::string>& warnings,
                     const fs::path& bakeCache) {
    BakeTally levels;
    Scene& scene = world.scene;
    LodTable& lodTable = world.lods;
    const NodeId groupingNode = beginGrouping(cfg.grouping, scene, world.grouping);
    const NodeId objectParent = groupingNode != kNoNode && cfg.grouping.objects ? groupingNode : scene.root();
    for (const ObjectConfig& o : cfg.objects) {
        glm::mat4 m = glm::translate(glm::mat4(1.0f), o.position);
        m = glm::rotate(m, glm::radians(o.rotationDegrees.z), {0, 0, 1});
        m = glm::rotate(m, glm::radians(o.rotationDegrees.y), {0, 1, 0});
        m = glm::rotate(m, glm::radians(o.rotationDegrees.x), {1, 0, 0});
        m = glm::scale(m, o.scale);
        const NodeId place = scene.addTransform(objectParent, m, o.name);
        if (!o.visible) setOpacity(world.opacity, place, 0.0f);
        if (glm::length(o.velocity) > 0.0f)
            world.motions.push_back({.node = place, .rest = m, .velocity = o.velocity, .range = o.rangeMetres});
        MeshPlacer placeMesh;
        if (!o.lodRatios.empty())
            placeMesh = [&](NodeId parent, MeshPart part) {
                if (bakeCache.empty()) {
                    addGeneratedLod(scene, lodTable, parent, part, o.lodRatios, lodSettings(o));
                    ++levels.baked;
                    return;
                }
                LoadedOrSimplified l =
                    loadOrSimplifyLevels(bakeCache / bakeCacheFileName(cfg.file, o.name, part.geometry, ".lod"),
                                         scene.geometry(part.geometry), o.lodRatios);
                ++(l.loaded ? levels.loaded : levels.baked);
                if (!l.loaded) spdlog::info(joinText("levels of '", o.name, "': ", l.note));
                addLodLevels(scene, lodTable, parent, part, std::move(l.levels), lodSettings(o));
            };
        if (!o.model.empty()) {
            const std::string object =
                cfg.file.string() + ":" + std::to_string(o.line) + ": object '" + o.name + "' skipped: ";
            try {
                ParsedModel parsed = parseModel(o.model);
                // Checked before placing, so that a wrong name leaves no
                // unanimated copy in the scene.
                std::optional<std::size_t> clip;
                if (!o.animation.empty() && !(clip = findAnimation(parsed.animations, o.animation))) {
                    warnings.push_back(object + "model '" + o.model.string() + "' has no animation '" + o.animation +
                                       "'; its animations: " + listAnimations(parsed.animations));
                    continue;
                }
                LoadedModel loaded = placeModel(std::move(parsed), scene, place, o.model.stem().string(), placeMesh);
                for (const std::string& w : loaded.warnings) warnings.push_back(o.model.string() + ": " + w);
                if (clip) {
                    world.animations.push_back(
                        {.player = AnimationPlayer(loaded.animations[*clip],
                                                   {.loop = o.animationLoop, .speed = o.animationSpeed}),
                         .node = place});
                    if (!o.animationPlaying) world.animations.back().player.stop();
                }
                world.objects.push_back({o.name, place, std::move(loaded.animations)});
            } catch (const ModelError& e) {
                warnings.push_back(object + e.what());
            }
            continue;
        }
        Geometry g = o.shape == "sphere" ? makeUvSphere(o.radius, 48, 24) : makeBox(o.size);
        Material mat;
        mat.name = o.name;
        mat.baseColor = o.color;
        if (o.color.a < 1.0f) mat.alphaMode = AlphaMode::Blend;
        const MeshPart part{scene.addGeometry(std::move(g)), scene.addMaterial(std::move(mat))};
        if (placeMesh)
            placeMesh(place, part);
        else
            scene.addMesh(place, part, o.name);
        world.objects.push_back({o.name, place});
    }
    finishGrouping(cfg.grouping, scene, groupingNode, world.grouping, lodTable);
    // A mover or an animated object inside the grouping node rebuilds only its own branch.
    for (ObjectMotion& motion : world.motions)
        std::tie(motion.groupingNode, motion.groupingObject) = groupingSlot(world, motion.node);
    for (ObjectAnimation& animation : world.animations)
        std::tie(animation.groupingNode, animation.groupingObject) = groupingSlot(world, animation.node);
    addPointClouds(cfg.pointClouds, cfg.file, scene, world.pointClouds, warnings);
    return levels;
}

SceneFile loadSceneFile(const fs::path& file) {
    SceneFile out;
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext == ".yaml" || ext == ".yml") {
        const StationConfig cfg = loadStationConfig(file);
        buildScene(cfg, out.world, out.warnings);
        if (cfg.camera.given) out.camera = cameraView(cfg.camera);
        out.background = cfg.render.background;
        out.environment = cfg.render.environment;
        out.environmentIntensity = cfg.render.environmentIntensity;
        return out;
    }
    LoadedModel loaded = loadModel(file, out.world.scene, out.world.scene.root());
    out.warnings = std::move(loaded.warnings);
    out.notDrawn = std::move(loaded.notDrawn);
    out.animations = std::move(loaded.animations);
    out.skins = std::move(loaded.skins);
    out.background = glm::vec4(0.0f);
    return out;
}

}  // namespace arcomp
