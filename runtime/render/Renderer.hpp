#pragma once
// Draws a select pass's DrawList into the bound framebuffer, each item with
// its own shading level (unlit, flat, Gouraud, Phong: what each evaluates of
// glTF's metallic-roughness material is listed at the shader in
// Renderer.cpp). Geometry and textures go to the GPU the first time they are
// drawn and stay there. Light: one directional light plus image-based light
// from an environment (built-in neutral studio unless setEnvironment says
// otherwise). A mesh part with a skin (MeshPart::skin) is posed on the GPU by
// the scene's joint matrices, up to kMaxJointsPerDraw joints.
//
//   Renderer renderer;                       // a context must be current
//   renderer.setEnvironment(prefilterEnvironment(loadEnvironment("hall.hdr")));  // optional
//   select(scene, view, {}, list);
//   renderer.draw(scene, list, view, {.clearColor = {0, 0, 0, 0}});
//
// Output is premultiplied RGBA with sRGB-encoded colour: lighting happens in
// linear light (textures are decoded from sRGB, factors are linear as glTF
// says) and is encoded once at the end, so the compositor can blend layers
// with "over" directly. There is no tone mapping: what exceeds 1 clips, as
// in three.js with NoToneMapping and sRGB output.

#include "graph/animation/Skin.hpp"
#include "graph/core/DrawList.hpp"
#include "graph/core/View.hpp"
#include "runtime/gl/GlHandle.hpp"
#include "runtime/gl/ShaderProgram.hpp"
#include "runtime/render/ImageBasedLight.hpp"

#include <array>
#include <map>
#include <optional>
#include <tuple>
#include <vector>

namespace arcomp {

struct RenderSettings {
    std::optional<glm::vec4> clearColor = glm::vec4(0.0f);                     // nullopt: draw over what is there
    glm::vec3 lightDirection = glm::normalize(glm::vec3(-0.4f, 0.8f, 0.45f));  // towards the light, world space
    // Linear colour and intensity of the directional light, as three.js's
    // DirectionalLight takes them: a white diffuse surface facing it
    // reflects intensity / pi.
    glm::vec3 lightColor{1.0f};
    float lightIntensity = 1.5f;
    float environmentIntensity = 1.0f;  // scales the image-based light
    // Every item opaque and unlit: for passes that need where items are, not
    // how they look (the holdout's depth, a shadow mask), where a blended or
    // fading item must still count.
    bool coverageOnly = false;
};

class Renderer {
public:
    Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Replaces the image-based light (the built-in neutral one by default).
    void setEnvironment(const ImageBasedLight& light);

    void draw(const Scene& scene, const DrawList& list, const View& view, const RenderSettings& settings = {});
    // Drops every GPU resource, for when the scene is replaced.
    void forget();

    std::size_t trianglesDrawn() const { return trianglesDrawn_; }

private:
    struct GpuGeometry {
        GlVertexArray vao;
        GlBuffer vertices, indices;
        GLsizei indexCount = 0;
        bool hasTangents = false, hasColors = false, hasSkinInfluences = false;
    };
    // One shading level's program and its uniforms' locations, looked up
    // once: a draw item sets a dozen uniforms. `textured`: the variant for
    // materials with a texture in any slot.
    struct MeshProgram {
        MeshProgram(Shading shading, bool skinned, bool textured);
        ShaderProgram program;
        GLint model, viewProjection, normalMatrix, eye, lightDirection, lightRadiance, irradiance, environmentIntensity,
            specularLevels, specularEnvironment, splitSum, baseColor, metallic, roughness, emissive, normalScale,
            occlusionStrength, alphaMode, alphaCutoff, fade, doubleSided, hasTangents, texCoord, uvTransform,
            jointMatrices;  // -1 unless skinned
    };
    // One GL texture per image, colour space and sampler: an image can be
    // both a colour (sRGB-decoded) and data, and sampled in different ways.
    using TextureKey = std::tuple<int, bool, TextureFilter, TextureFilter, TextureWrap, TextureWrap>;
    const GpuGeometry& geometry(const Scene& scene, std::uint32_t id);
    const MeshProgram& program(Shading shading, bool skinned, bool textured);
    GLuint texture(const Scene& scene, const TextureRef& ref, bool srgb);
    void drawItem(const Scene& scene, const DrawItem& item, const View& view, const RenderSettings& settings);

    // By shading, then skinned and textured (program()).
    std::array<std::optional<MeshProgram>, kShadingCount * 4> programs_;
    std::vector<float> jointRows_;  // scratch: a skinned draw's joint matrices as the shader takes them
    const Scene* scene_ = nullptr;
    std::vector<GpuGeometry> geometries_;
    std::map<TextureKey, GlTexture> textures_;
    GlTexture specular_, splitSum_;
    std::array<glm::mat4, 3> irradiance_{};
    int specularLevels_ = 0;
    std::size_t trianglesDrawn_ = 0;
};

}  // namespace arcomp
