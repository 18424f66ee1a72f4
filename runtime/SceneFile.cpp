#include "runtime/SceneFile.hpp"

#include "graph/ModelLoader.hpp"
#include "runtime/GroupingSetup.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace arcomp {

namespace fs = std::filesystem;

View cameraView(const CameraConfig& c) {
    return View::lookAt(c.eye, c.target, c.up, c.fovyDegrees, c.size, c.near, c.far);
}

void buildScene(const StationConfig& cfg, Scene& scene, std::vector<std::string>& warnings, GroupingNodes* grouping,
                LodTable* lods, PointCloudNodes* clouds) {
    GroupingNodes ownGrouping;
    LodTable ownLods;
    const NodeId groupingNode = beginGrouping(cfg.grouping, scene, grouping ? *grouping : ownGrouping);
    const NodeId objectParent = groupingNode != kNoNode && cfg.grouping.objects ? groupingNode : scene.root();
    for (const ObjectConfig& o : cfg.objects) {
        glm::mat4 m = glm::translate(glm::mat4(1.0f), o.position);
        m = glm::rotate(m, glm::radians(o.rotationDegrees.z), {0, 0, 1});
        m = glm::rotate(m, glm::radians(o.rotationDegrees.y), {0, 1, 0});
        m = glm::rotate(m, glm::radians(o.rotationDegrees.x), {1, 0, 0});
        m = glm::scale(m, o.scale);
        const NodeId place = scene.addTransform(objectParent, m, o.name);
        if (!o.model.empty()) {
            try {
                const LoadedModel loaded = loadModel(o.model, scene, place);
                for (const std::string& w : loaded.warnings) warnings.push_back(o.model.string() + ": " + w);
            } catch (const ModelError& e) {
                warnings.push_back(cfg.file.string() + ":" + std::to_string(o.line) + ": object '" + o.name +
                                   "' skipped: " + e.what());
            }
            continue;
        }
        Geometry g = o.shape == "sphere" ? makeUvSphere(o.radius, 48, 24) : makeBox(o.size);
        Material mat;
        mat.name = o.name;
        mat.baseColor = o.color;
        if (o.color.a < 1.0f) mat.alphaMode = AlphaMode::Blend;
        scene.addMesh(place, {scene.addGeometry(std::move(g)), scene.addMaterial(std::move(mat))}, o.name);
    }
    finishGrouping(cfg.grouping, scene, groupingNode, grouping ? *grouping : ownGrouping, lods ? *lods : ownLods);
    if (clouds) addPointClouds(cfg.pointClouds, cfg.file, scene, *clouds, warnings);
}

SceneFile loadSceneFile(const fs::path& file) {
    SceneFile out;
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext == ".yaml" || ext == ".yml") {
        const StationConfig cfg = loadStationConfig(file);
        buildScene(cfg, out.scene, out.warnings, &out.grouping, &out.lods, &out.pointClouds);
        if (cfg.camera.given) out.camera = cameraView(cfg.camera);
        out.background = cfg.render.background;
        return out;
    }
    const LoadedModel loaded = loadModel(file, out.scene, out.scene.root());
    out.warnings = loaded.warnings;
    out.background = glm::vec4(0.0f);
    return out;
}

} // namespace arcomp
