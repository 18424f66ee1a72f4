#pragma once
// Draws a select pass's DrawList into the bound framebuffer, each item with
// its own shading level (unlit, flat, Gouraud, Phong). Geometry and textures
// go to the GPU the first time they are drawn and stay there.
//
//   Renderer renderer;                       // a context must be current
//   select(scene, view, {}, list);
//   renderer.draw(scene, list, view, {.clearColor = {0, 0, 0, 0}});
//
// Output is premultiplied RGBA with sRGB-encoded colour: lighting happens in
// linear light (textures are decoded from sRGB, factors are linear as glTF
// says) and is encoded once at the end, so the compositor can blend layers
// with "over" directly.

#include "graph/core/DrawList.hpp"
#include "graph/core/View.hpp"
#include "runtime/GlHandle.hpp"
#include "runtime/ShaderProgram.hpp"

#include <array>
#include <optional>
#include <vector>

namespace arcomp {

struct RenderSettings {
    std::optional<glm::vec4> clearColor = glm::vec4(0.0f);  // nullopt: draw over what is there
    glm::vec3 lightDirection = glm::normalize(glm::vec3(-0.4f, 0.8f, 0.45f));  // towards the light, world space
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

    void draw(const Scene& scene, const DrawList& list, const View& view, const RenderSettings& settings = {});
    // Drops every GPU resource, for when the scene is replaced.
    void forget();

    std::size_t trianglesDrawn() const { return trianglesDrawn_; }

private:
    struct GpuGeometry {
        GlVertexArray vao;
        GlBuffer vertices, indices;
        GLsizei indexCount = 0;
    };
    // One shading level's program and its uniforms' locations, looked up
    // once: a draw item sets a dozen uniforms.
    struct MeshProgram {
        explicit MeshProgram(Shading shading);
        ShaderProgram program;
        GLint model, viewProjection, normalMatrix, eye, lightDirection, baseColor, specular, alphaMode, alphaCutoff,
            fade, hasTexture, baseTexture;
    };
    const GpuGeometry& geometry(const Scene& scene, std::uint32_t id);
    GLuint texture(const Scene& scene, int image);
    void drawItem(const Scene& scene, const DrawItem& item, const View& view, const RenderSettings& settings);

    std::array<std::optional<MeshProgram>, kShadingCount> programs_;
    const Scene* scene_ = nullptr;
    std::vector<GpuGeometry> geometries_;
    std::vector<GlTexture> textures_;
    std::size_t trianglesDrawn_ = 0;
};

} // namespace arcomp
