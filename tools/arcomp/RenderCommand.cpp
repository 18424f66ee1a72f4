// arcomp render <scene> --out F.png: one headless frame of a model or a
// station config's scene. arcomp environment --out F.hdr: the light it uses.

#include "graph/animation/AnimationPlayer.hpp"
#include "graph/core/SelectPass.hpp"
#include "runtime/gl/GlContext.hpp"
#include "runtime/gl/RenderTarget.hpp"
#include "runtime/render/Environment.hpp"
#include "runtime/render/ImpostorBaker.hpp"
#include "runtime/render/PointCloudLayer.hpp"
#include "runtime/render/Renderer.hpp"
#include "runtime/station/ImageFile.hpp"
#include "runtime/station/SceneFile.hpp"
#include "tools/cli/CliParse.hpp"
#include "tools/cli/Command.hpp"

#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>

namespace arcomp {
namespace {

struct RenderOptions {
    std::string scene, out, size = "640x480", eye, target, shading = "phong", gl = "auto", lightDirection, lightColor,
                            environment, animation;
    float fovy = 0.0f;  // 0: the station camera's, else 45
    std::optional<float> environmentIntensity;
    float lightIntensity = RenderSettings{}.lightIntensity;
    double time = -1.0;  // below zero: not given
};

// --time poses a config's animated objects as a station would at that frame
// time, or one of a model file's animations (--animation, the first by
// default).
void pose(SceneFile& file, const RenderOptions& o) {
    if (o.time < 0.0) {
        if (!o.animation.empty()) throw InputError("--animation needs --time");
        return;
    }
    if (!file.world.animations.empty()) {
        if (!o.animation.empty())
            throw InputError("--animation: a station config names each object's animation itself");
        animateObjects(file.world, o.time);
        return;
    }
    if (file.animations.empty()) throw InputError("--time: " + o.scene + " has no animations");
    std::size_t chosen = 0;
    if (!o.animation.empty()) {
        const auto named = std::find_if(file.animations.begin(), file.animations.end(),
                                        [&](const ModelAnimation& a) { return a.clip.name == o.animation; });
        if (named != file.animations.end()) {
            chosen = static_cast<std::size_t>(named - file.animations.begin());
        } else if (std::all_of(o.animation.begin(), o.animation.end(), [](char c) { return c >= '0' && c <= '9'; }) &&
                   o.animation.size() < 6 && std::stoul(o.animation) < file.animations.size()) {
            chosen = std::stoul(o.animation);
        } else {
            throw InputError("--animation '" + o.animation + "': " + o.scene + " has " +
                             std::to_string(file.animations.size()) + " animations; `arcomp inspect` lists them");
        }
    }
    // A still at a time: past the clip's end it holds the last pose, as a
    // viewer's timeline does (a station loops by default instead).
    AnimationPlayer(file.animations[chosen], {.loop = false}).apply(file.world.scene, o.time);
}

int render(const RenderOptions& o) {
    const glm::ivec2 size = parseSize(o.size, "--size");
    const auto shading = parseShading(o.shading);
    if (!shading) throw InputError("--shading '" + o.shading + "': expected unlit, flat, gouraud or phong");
    GlRequest request;
    try {
        request = parseGlRequest(o.gl);
    } catch (const std::invalid_argument& e) {
        throw InputError(std::string("--gl: ") + e.what());
    }
    SceneFile file = loadSceneFile(o.scene);
    for (const std::string& w : file.warnings) std::cerr << "warning: " << w << "\n";
    pose(file, o);
    World& world = file.world;
    Scene& scene = world.scene;
    scene.update();

    View view = file.camera ? *file.camera : View::framing(scene.bound(), 45.0f, size);
    if (!o.eye.empty() || !o.target.empty() || view.viewport != size || o.fovy > 0.0f) {
        const Sphere b = scene.bound().empty() ? Sphere{glm::vec3(0.0f), 1.0f} : scene.bound();
        const glm::vec3 eye = o.eye.empty() ? view.eye : parseVec3(o.eye, "--eye");
        const glm::vec3 target =
            o.target.empty() ? (file.camera ? view.eye + view.forward : b.center) : parseVec3(o.target, "--target");
        const float distance = glm::length(eye - b.center);
        const float fovy = o.fovy > 0.0f ? o.fovy : glm::degrees(view.fovyRadians);
        view = View::lookAt(eye, target, {0.0f, 1.0f, 0.0f}, fovy, size,
                            std::max(1e-3f * distance, distance - 2.0f * b.radius), distance + 2.0f * b.radius);
    }

    RenderSettings settings{.clearColor = file.background,
                            .lightIntensity = o.lightIntensity,
                            .environmentIntensity = o.environmentIntensity.value_or(file.environmentIntensity)};
    if (!o.lightDirection.empty()) {
        const glm::vec3 towards = parseVec3(o.lightDirection, "--light-direction");
        if (glm::length(towards) == 0.0f) throw InputError("--light-direction: the zero vector has no direction");
        settings.lightDirection = glm::normalize(towards);
    }
    if (!o.lightColor.empty()) {
        settings.lightColor = parseVec3(o.lightColor, "--light-color");
        if (glm::any(glm::lessThan(settings.lightColor, glm::vec3(0.0f))))
            throw InputError("--light-color '" + o.lightColor + "': expected linear R,G,B, none below 0");
    }

    auto context = HeadlessContext::create(request);
    bakeImpostors(scene, world.grouping, view.eye);  // for grouping nodes that use them; needs the context
    RenderTarget target(size);
    target.bind();
    Renderer renderer;
    // --environment over the config's render.environment over neutral.
    const std::string environment = !o.environment.empty()     ? o.environment
                                    : file.environment.empty() ? std::string("neutral")
                                                               : file.environment.string();
    if (environment != "neutral") renderer.setEnvironment(prefilterEnvironment(loadEnvironment(environment)));
    DrawList list;
    select(world, view, {.shading = *shading}, list);
    renderer.draw(scene, list, view, settings);
    std::optional<PointCloudLayer> clouds;
    if (world.pointClouds.size()) {
        clouds.emplace();
        clouds->draw(scene, world.pointClouds, list.pointClouds, view);
    }
    const Image image = target.read();
    writePng(o.out, image);
    std::size_t covered = 0;
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) covered += image.rgba[i] > 0;
    std::cout << "wrote " << o.out << ": " << size.x << "x" << size.y << ", " << list.items.size() << " meshes, "
              << renderer.trianglesDrawn() << " triangles, "
              << (clouds ? std::to_string(clouds->cloudsDrawn()) + " point clouds, " : std::string())
              << toString(context->api()) << ", "
              << 100.0 * static_cast<double>(covered) / static_cast<double>(size.x * size.y) << "% covered\n";
    return kExitOk;
}

const bool registered = registerCommand(
    {"render", "Render one frame of a model (.gltf, .glb, .obj) or a station config (.yaml) to a PNG",
     [](CommandLine& line) {
         auto o = std::make_shared<RenderOptions>();
         auto environmentIntensity = std::make_shared<float>(-1.0f);  // below the range: not given
         line.option("scene", o->scene, "Model or station config").required();
         line.option("--out", o->out, "PNG file to write").required();
         line.option("--size", o->size, "Image size WIDTHxHEIGHT").showDefault();
         line.option("--eye", o->eye, "Camera position X,Y,Z (default: frames the scene)");
         line.option("--target", o->target, "Point looked at X,Y,Z (default: the scene's centre)");
         line.option("--fovy", o->fovy, "Vertical field of view in degrees (default: the station camera's, else 45)")
             .range(1.0, 179.0);
         line.option("--light-direction", o->lightDirection,
                     "Direction towards the light X,Y,Z, world space (default: from above, left and front)");
         line.option("--light-color", o->lightColor, "The directional light's linear colour R,G,B (default: white)");
         line.option("--time", o->time,
                     "Pose animations at this many seconds: a config's objects, or a model's --animation")
             .range(0.0, 1e9);
         line.option("--animation", o->animation,
                     "A model file's animation to pose at --time, by name or index (default: the first)");
         line.option("--shading", o->shading, "unlit, flat, gouraud or phong").showDefault();
         line.option("--gl", o->gl, "OpenGL API: auto, gl33 or es3").showDefault();
         line.option(
             "--environment", o->environment,
             "Image-based light: neutral, or an equirectangular .hdr or .png (default: the config's, else neutral)");
         line.option("--environment-intensity", *environmentIntensity,
                     "Scales the image-based light (default: the config's, else 1)")
             .range(0.0, 1000.0);
         line.option("--light-intensity", o->lightIntensity,
                     "The directional light, as three.js's DirectionalLight.intensity")
             .showDefault();
         return [o, environmentIntensity] {
             if (*environmentIntensity >= 0.0f) o->environmentIntensity = *environmentIntensity;
             return render(*o);
         };
     }});

// Writes an environment as a Radiance .hdr, so that a reference renderer
// (three.js's HDRLoader, as tools/gltf-reference uses) can be lit exactly as `render` lights.
int writeEnvironment(const std::string& source, const std::string& out) {
    const Environment env = environmentFromOption(source);
    writeRadianceHdr(out, env);
    std::cout << "wrote " << out << ": " << env.width << "x" << env.height << " equirectangular, linear RGB\n";
    return kExitOk;
}

const bool registeredEnvironment = registerCommand(
    {"environment", "Write the image-based light render uses (the built-in neutral one by default) as a Radiance .hdr",
     [](CommandLine& line) {
         auto source = std::make_shared<std::string>("neutral");
         auto out = std::make_shared<std::string>();
         line.option("--out", *out, ".hdr file to write").required();
         line.option("--source", *source, "neutral, or an equirectangular .hdr or .png to convert").showDefault();
         return [source, out] { return writeEnvironment(*source, *out); };
     }});

}  // namespace
}  // namespace arcomp
