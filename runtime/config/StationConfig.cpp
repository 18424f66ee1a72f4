#include "runtime/config/StationConfig.hpp"

#include "graph/core/BadInput.hpp"
#include "runtime/config/CameraFile.hpp"
#include "runtime/config/TriggerConfig.hpp"
#include "runtime/config/YamlMap.hpp"
#include "runtime/config/ZoneConfig.hpp"

#include <limits>

namespace arcomp {

namespace {

constexpr double kLarge = 1e6;  // metres; anything beyond is a typo

void readObjectLod(YamlMap& lod, ObjectConfig& o) {
    std::string policy = "distance";
    lod.choice("policy", policy, {"distance", "screen_size", "gaze", "screen_size_gaze"});
    o.lodPolicy = policy == "distance"      ? LodPolicy::Distance
                  : policy == "screen_size" ? LodPolicy::ScreenSize
                  : policy == "gaze"        ? LodPolicy::GazeAcuity
                                            : LodPolicy::ScreenSizeTimesAcuity;
    if (!lod.has("ratios")) lod.report().add(lod.mark(), lod.where() + ": 'ratios' is required (e.g. [1, 0.25, 0.05])");
    if (!lod.has("thresholds"))
        lod.report().add(lod.mark(), lod.where() + ": 'thresholds' is required, one fewer than ratios");
    lod.numbers("ratios", o.lodRatios, 1e-4, 1.0);
    lod.numbers("thresholds", o.lodThresholds, 0.0, kLarge);
    lod.number("fade_s", o.lodFadeSeconds, 0.0, 10.0);
    const std::size_t levels = o.lodRatios.size();
    if (levels > 0) {
        bool ok = levels <= kMaxLodLevels && o.lodRatios.front() == 1.0f && o.lodThresholds.size() + 1 == levels;
        for (std::size_t i = 1; ok && i < levels; ++i) ok = o.lodRatios[i] < o.lodRatios[i - 1];
        // Distance grows towards coarser levels; the other metrics shrink.
        const bool ascending = o.lodPolicy == LodPolicy::Distance;
        for (std::size_t i = 1; ok && i < o.lodThresholds.size(); ++i)
            ok = ascending ? o.lodThresholds[i] > o.lodThresholds[i - 1] : o.lodThresholds[i] < o.lodThresholds[i - 1];
        if (!ok)
            lod.report().add(lod.mark(), lod.where() + ": expected 2 to " + std::to_string(kMaxLodLevels) +
                                             " ratios falling from 1, and one threshold fewer (" +
                                             (ascending ? "rising" : "falling") + " for policy " + policy + ")");
    }
    lod.finish();
}

ObjectConfig readObject(YamlMap& m, std::size_t index) {
    ObjectConfig o;
    o.line = m.mark().line + 1;
    o.name = "object" + std::to_string(index);
    m.text("name", o.name);
    const bool hasModel = m.has("model");
    const bool hasShape = m.has("shape");
    if (hasModel == hasShape)
        m.report().add(m.mark(), m.where() + ": give exactly one of 'model' (a .gltf, .glb or .obj file) or 'shape'");
    m.path("model", o.model, true);
    m.choice("shape", o.shape, {"box", "sphere"});
    m.vec3("size", o.size);
    m.number("radius", o.radius, 1e-6, kLarge);
    m.vec4("color", o.color);
    m.vec3("position", o.position);
    m.vec3("rotation_deg", o.rotationDegrees);
    // A single number scales uniformly.
    if (m.has("scale")) {
        const YAML::Node s = m.take("scale");
        double uniform = 0;
        if (s.IsScalar() && YAML::convert<double>::decode(s, uniform) && uniform > 0)
            o.scale = glm::vec3(static_cast<float>(uniform));
        else if (s.IsSequence() && s.size() == 3)
            m.vec3("scale", o.scale);
        else
            m.report().add(s.Mark(), m.where() + ".scale: expected a positive number or a list of 3 numbers");
    }
    if (m.has("lod")) {
        YamlMap lod = m.map("lod");
        readObjectLod(lod, o);
    }
    if (m.has("motion")) {
        YamlMap motion = m.map("motion");
        motion.vec3("velocity", o.velocity, Required::Yes);
        // Required: a mover with no turning point would leave for good on a
        // station that runs all day.
        motion.number("range_m", o.rangeMetres, 1e-3, kLarge, Required::Yes);
        if (glm::length(o.velocity) == 0.0f)
            motion.report().add(motion.mark(), motion.where() + ".velocity: must not be zero");
        motion.finish();
    }
    // Which animation exists is known once the model is loaded (buildScene,
    // and so `arcomp check`); here only the shape of the keys.
    if (m.has("animation")) {
        if (!hasModel) m.report().add(m.mark(), m.where() + ".animation: only a model has animations");
        m.text("animation", o.animation, Required::Yes);
        if (o.animation.empty()) m.report().add(m.mark(), m.where() + ".animation: give an animation's name or index");
    }
    for (const char* key : {"loop", "speed", "playing"})
        if (m.has(key) && !m.has("animation"))
            m.report().add(m.mark(), m.where() + "." + key + ": only with 'animation'");
    m.boolean("loop", o.animationLoop);
    // Backwards play is not supported: a loop would need its own start.
    m.number("speed", o.animationSpeed, 1e-3, 1e3);
    m.boolean("playing", o.animationPlaying);
    m.boolean("visible", o.visible);
    for (int i = 0; i < 4; ++i)
        if (o.color[i] < 0.0f || o.color[i] > 1.0f) {
            m.report().add(m.mark(), m.where() + ".color: components must lie in 0..1 (linear RGBA)");
            break;
        }
    m.finish();
    return o;
}

}  // namespace

StationConfig loadStationConfig(const std::filesystem::path& file) {
    ConfigReport report(file);
    StationConfig cfg;
    cfg.file = file;
    YAML::Node rootNode = loadYamlFile(report);
    if (!rootNode) report.throwIfAny();
    YamlMap root(rootNode, "", report);

    YamlMap scene = root.map("scene", Required::Yes);
    auto objects = scene.list("objects", Required::Yes);
    for (std::size_t i = 0; i < objects.size(); ++i) cfg.objects.push_back(readObject(objects[i], i));
    scene.finish();

    if (root.has("camera")) {
        YamlMap camera = root.map("camera");
        cfg.camera.given = true;
        camera.path("calibration", cfg.camera.calibration, true);
        if (!cfg.camera.calibration.empty()) {
            for (const char* key : {"eye", "target", "up", "fovy_deg"})
                if (camera.has(key))
                    camera.report().add(
                        camera.mark(),
                        std::string("camera.") + key +
                            ": not used with camera.calibration, which gives the real camera's pose and field of view");
            if (std::filesystem::exists(cfg.camera.calibration)) {
                try {
                    cfg.camera.calibrated = readCameraFile(cfg.camera.calibration);
                } catch (const BadInput& e) {
                    camera.report().add(camera.mark(), std::string("camera.calibration: ") + e.what());
                }
            }
        }
        const Required pose = cfg.camera.calibration.empty() ? Required::Yes : Required::No;
        camera.vec3("eye", cfg.camera.eye, pose);
        camera.vec3("target", cfg.camera.target, pose);
        camera.vec3("up", cfg.camera.up);
        camera.number("fovy_deg", cfg.camera.fovyDegrees, 1.0, 179.0);
        camera.vec2i("size", cfg.camera.size, 1, 16384);
        if (cfg.camera.calibrated && !camera.has("size")) cfg.camera.size = cfg.camera.calibrated->intrinsics.imageSize;
        camera.number("near", cfg.camera.near, 1e-6, kLarge);
        camera.number("far", cfg.camera.far, 1e-6, kLarge);
        if (cfg.camera.far <= cfg.camera.near)
            camera.report().add(camera.mark(), "camera: far must be larger than near");
        if (cfg.camera.calibration.empty() && glm::length(cfg.camera.eye - cfg.camera.target) <= 0.0f)
            camera.report().add(camera.mark(), "camera: eye and target must differ");
        camera.finish();
    }

    YamlMap render = root.map("render");
    std::string shading = "phong";
    render.choice("shading", shading, {"unlit", "flat", "gouraud", "phong"});
    cfg.render.shading = *parseShading(shading);
    render.choice("gl", cfg.render.gl, {"auto", "gl33", "es3"});
    render.vec4("background", cfg.render.background);
    if (render.has("environment")) {
        std::string environment;
        render.text("environment", environment);
        if (environment.empty())
            render.report().add(render.mark(),
                                "render.environment: expected 'neutral' or an equirectangular .hdr or .png file");
        else if (environment != "neutral") {
            std::filesystem::path p(environment);
            if (p.is_relative()) p = file.parent_path() / p;
            cfg.render.environment = p.lexically_normal();
        }
    }
    render.number("environment_intensity", cfg.render.environmentIntensity, 0.0, 1000.0);
    render.finish();

    readCompositingConfig(root, cfg.compositing);
    readOperatorConfig(root, cfg.operation);

    readBudgetConfig(root, cfg.budget);
    readGroupingConfig(root, cfg.grouping);
    readGazeConfig(root, cfg.gaze);
    readPointCloudConfig(root, cfg.pointClouds);
    readShowControlConfig(root, cfg.showControl);
    readZoneConfig(root, cfg.camera.calibrated, cfg.zones);
    readTriggerConfig(root,
                      {.objects = cfg.objects,
                       .zones = cfg.zones,
                       .showControl = cfg.showControl,
                       .calibrated = cfg.camera.calibrated.has_value()},
                      cfg.triggers);
    root.finish();
    report.throwIfAny();
    return cfg;
}

}  // namespace arcomp
