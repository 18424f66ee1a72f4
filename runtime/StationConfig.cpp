#include "runtime/StationConfig.hpp"

#include "runtime/YamlMap.hpp"

#include <limits>

namespace arcomp {

namespace {

constexpr double kLarge = 1e6;  // metres; anything beyond is a typo

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
        if (s.IsScalar() && YAML::convert<double>::decode(s, uniform) && uniform > 0) o.scale = glm::vec3(static_cast<float>(uniform));
        else if (s.IsSequence() && s.size() == 3) m.vec3("scale", o.scale);
        else m.report().add(s.Mark(), m.where() + ".scale: expected a positive number or a list of 3 numbers");
    }
    for (int i = 0; i < 4; ++i)
        if (o.color[i] < 0.0f || o.color[i] > 1.0f) {
            m.report().add(m.mark(), m.where() + ".color: components must lie in 0..1 (linear RGBA)");
            break;
        }
    m.finish();
    return o;
}

} // namespace

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
        camera.vec3("eye", cfg.camera.eye, Required::Yes);
        camera.vec3("target", cfg.camera.target, Required::Yes);
        camera.vec3("up", cfg.camera.up);
        camera.number("fovy_deg", cfg.camera.fovyDegrees, 1.0, 179.0);
        camera.vec2i("size", cfg.camera.size, 1, 16384);
        camera.number("near", cfg.camera.near, 1e-6, kLarge);
        camera.number("far", cfg.camera.far, 1e-6, kLarge);
        if (cfg.camera.far <= cfg.camera.near) camera.report().add(camera.mark(), "camera: far must be larger than near");
        if (glm::length(cfg.camera.eye - cfg.camera.target) <= 0.0f)
            camera.report().add(camera.mark(), "camera: eye and target must differ");
        camera.finish();
    }

    YamlMap render = root.map("render");
    std::string shading = "phong";
    render.choice("shading", shading, {"unlit", "flat", "gouraud", "phong"});
    cfg.render.shading = *parseShading(shading);
    render.choice("gl", cfg.render.gl, {"auto", "gl33", "es3"});
    render.vec4("background", cfg.render.background);
    render.finish();

    readCompositingConfig(root, cfg.compositing);
    readOperatorConfig(root, cfg.operation);

    readBudgetConfig(root, cfg.budget);
    readGroupingConfig(root, cfg.grouping);
    readPointCloudConfig(root, cfg.pointClouds);
    root.finish();
    report.throwIfAny();
    return cfg;
}

} // namespace arcomp
