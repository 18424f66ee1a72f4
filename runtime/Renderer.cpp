#include "runtime/Renderer.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace arcomp {

using namespace gl;

namespace {

// One source for all four levels; SHADING picks the lighting model:
// 0 unlit, 1 flat (face normal from screen-space derivatives, so no
// per-face vertices are needed), 2 Gouraud (per vertex), 3 Phong (per pixel,
// Blinn's half vector).
const char* const kMeshShader = R"(
#ifdef VERTEX
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aTexcoord;
#define VARYING out
#else
#define VARYING in
#endif
VARYING vec3 vWorld;
VARYING vec3 vNormal;
VARYING vec2 vTexcoord;
VARYING vec3 vLight;

uniform mat4 uModel;
uniform mat4 uViewProjection;
uniform mat3 uNormalMatrix;
uniform vec3 uEye;
uniform vec3 uLightDirection;
uniform vec4 uBaseColor;
uniform float uSpecular;
uniform int uHasTexture;
uniform int uAlphaMode;
uniform float uAlphaCutoff;
uniform float uFade;
uniform sampler2D uBaseTexture;

// Ambient + diffuse + specular, as a factor on the base colour plus an
// additive highlight; both sides lit, since open meshes show their backs.
vec3 lightAt(vec3 n, vec3 p, vec3 base) {
    vec3 v = normalize(uEye - p);
    if (dot(n, v) < 0.0) n = -n;
    float diffuse = max(dot(n, uLightDirection), 0.0);
    vec3 h = normalize(uLightDirection + v);
    float highlight = diffuse > 0.0 ? pow(max(dot(n, h), 0.0), 32.0) * uSpecular : 0.0;
    return base * (0.25 + 0.75 * diffuse) + vec3(highlight);
}

#ifdef VERTEX
void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vWorld = world.xyz;
    vNormal = normalize(uNormalMatrix * aNormal);
    vTexcoord = aTexcoord;
#if SHADING == 2
    vLight = lightAt(vNormal, vWorld, vec3(1.0));
#else
    vLight = vec3(1.0);
#endif
    gl_Position = uViewProjection * world;
}
#else
out vec4 fragColor;
void main() {
    vec4 base = uBaseColor;
    if (uHasTexture != 0) {
        vec4 t = texture(uBaseTexture, vTexcoord);
        base *= vec4(pow(t.rgb, vec3(2.2)), t.a);
    }
    if (uAlphaMode == 1 && base.a < uAlphaCutoff) discard;
    float alpha = (uAlphaMode == 2 ? base.a : 1.0) * uFade;
#if SHADING == 0
    vec3 lit = base.rgb;
#elif SHADING == 1
    vec3 faceNormal = normalize(cross(dFdx(vWorld), dFdy(vWorld)));
    vec3 lit = lightAt(faceNormal, vWorld, base.rgb);
#elif SHADING == 2
    vec3 lit = base.rgb * vLight;
#else
    vec3 lit = lightAt(normalize(vNormal), vWorld, base.rgb);
#endif
    vec3 encoded = pow(clamp(lit, 0.0, 1.0), vec3(1.0 / 2.2));
    fragColor = vec4(encoded * alpha, alpha);
}
#endif
)";

} // namespace

// Lighting's uniforms are read only where a level lights (not unlit; the
// normal matrix not by flat either), and the compiler drops them elsewhere:
// those may be -1. The rest every level reads.
Renderer::MeshProgram::MeshProgram(Shading shading)
    : program(kMeshShader, "#define SHADING " + std::to_string(static_cast<int>(shading)) + "\n"),
      model(program.requiredLocation("uModel")),
      viewProjection(program.requiredLocation("uViewProjection")),
      normalMatrix(program.location("uNormalMatrix")),
      eye(program.location("uEye")),
      lightDirection(program.location("uLightDirection")),
      baseColor(program.requiredLocation("uBaseColor")),
      specular(program.location("uSpecular")),
      alphaMode(program.requiredLocation("uAlphaMode")),
      alphaCutoff(program.requiredLocation("uAlphaCutoff")),
      fade(program.requiredLocation("uFade")),
      hasTexture(program.requiredLocation("uHasTexture")),
      baseTexture(program.requiredLocation("uBaseTexture")) {}

Renderer::Renderer() {
    for (int s = 0; s < kShadingCount; ++s) programs_[static_cast<std::size_t>(s)].emplace(static_cast<Shading>(s));
}

void Renderer::forget() {
    geometries_.clear();
    textures_.clear();
    scene_ = nullptr;
}

const Renderer::GpuGeometry& Renderer::geometry(const Scene& scene, std::uint32_t id) {
    if (id >= geometries_.size()) geometries_.resize(scene.geometries().size());
    GpuGeometry& gpu = geometries_[id];
    if (gpu.vao) return gpu;
    const Geometry& g = scene.geometry(id);
    // Interleaved position, normal, texcoord: one buffer, one fetch stream.
    std::vector<float> vertices;
    vertices.reserve(g.positions.size() * 8);
    for (std::size_t i = 0; i < g.positions.size(); ++i) {
        const glm::vec2 uv = i < g.texcoords.size() ? g.texcoords[i] : glm::vec2(0.0f);
        vertices.insert(vertices.end(), {g.positions[i].x, g.positions[i].y, g.positions[i].z, g.normals[i].x,
                                         g.normals[i].y, g.normals[i].z, uv.x, uv.y});
    }
    gpu.vao = GlVertexArray::generate();
    glBindVertexArray(gpu.vao.get());
    gpu.vertices = GlBuffer::generate();
    glBindBuffer(GL_ARRAY_BUFFER, gpu.vertices.get());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(float)), vertices.data(), GL_STATIC_DRAW);
    gpu.indices = GlBuffer::generate();
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.indices.get());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(g.indices.size() * sizeof(std::uint32_t)),
                 g.indices.data(), GL_STATIC_DRAW);
    const GLsizei stride = 8 * sizeof(float);
    for (GLuint a = 0; a < 3; ++a) glEnableVertexAttribArray(a);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(3 * sizeof(float)));
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(6 * sizeof(float)));
    glBindVertexArray(0);
    gpu.indexCount = static_cast<GLsizei>(g.indices.size());
    return gpu;
}

GLuint Renderer::texture(const Scene& scene, int image) {
    if (image < 0) return 0;
    const auto index = static_cast<std::size_t>(image);
    if (index >= textures_.size()) textures_.resize(scene.images().size());
    if (textures_[index]) return textures_[index].get();
    const Image& img = scene.images()[index];
    GlTexture& t = textures_[index];
    t = GlTexture::generate();
    glBindTexture(GL_TEXTURE_2D, t.get());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, img.width, img.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    return t.get();
}

void Renderer::drawItem(const Scene& scene, const DrawItem& item, const View& view, const RenderSettings& settings) {
    const Material& m = scene.material(item.part.material);
    const Shading shading = m.unlit || settings.coverageOnly ? Shading::Unlit : item.shading;
    const MeshProgram& p = *programs_[static_cast<std::size_t>(shading)];
    p.program.use();
    const glm::mat4& model = item.model ? *item.model : scene.world(item.node);
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(model)));
    const glm::mat4 viewProjection = view.viewProjection();
    glUniformMatrix4fv(p.model, 1, GL_FALSE, glm::value_ptr(model));
    glUniformMatrix4fv(p.viewProjection, 1, GL_FALSE, glm::value_ptr(viewProjection));
    glUniformMatrix3fv(p.normalMatrix, 1, GL_FALSE, glm::value_ptr(normalMatrix));
    glUniform3f(p.eye, view.eye.x, view.eye.y, view.eye.z);
    glUniform3f(p.lightDirection, settings.lightDirection.x, settings.lightDirection.y, settings.lightDirection.z);
    const glm::vec4 base = m.baseColor * item.tint;
    glUniform4f(p.baseColor, base.r, base.g, base.b, base.a);
    glUniform1f(p.specular, 0.5f * (1.0f - m.roughness) + 0.1f);
    glUniform1i(p.alphaMode, static_cast<int>(m.alphaMode));
    glUniform1f(p.alphaCutoff, m.alphaCutoff);
    glUniform1f(p.fade, item.fade);
    const GLuint tex = texture(scene, m.baseColorTexture.image);
    glUniform1i(p.hasTexture, tex ? 1 : 0);
    glUniform1i(p.baseTexture, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, tex);
    if (m.doubleSided) glDisable(GL_CULL_FACE);
    else glEnable(GL_CULL_FACE);
    const GpuGeometry& g = geometry(scene, item.part.geometry);
    glBindVertexArray(g.vao.get());
    // A silhouette region draws its own range of the shared index list.
    const GLsizei count = item.indexCount ? static_cast<GLsizei>(item.indexCount) : g.indexCount;
    const auto offset = static_cast<std::uintptr_t>(item.indexCount ? item.firstIndex : 0) * sizeof(std::uint32_t);
    glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, reinterpret_cast<const void*>(offset));
    trianglesDrawn_ += static_cast<std::size_t>(count / 3);
}

void Renderer::draw(const Scene& scene, const DrawList& list, const View& view, const RenderSettings& settings) {
    if (scene_ != &scene) {
        forget();
        scene_ = &scene;
    }
    trianglesDrawn_ = 0;
    if (settings.clearColor) {
        const glm::vec4 c = *settings.clearColor;
        glClearColor(c.r * c.a, c.g * c.a, c.b * c.a, c.a);
        glDepthMask(GL_TRUE);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glCullFace(GL_BACK);

    // Opaque front to back (early depth rejection), then blended back to
    // front; a level fading in or out of an LOD cross-fade is blended.
    std::vector<const DrawItem*> opaque, blended;
    for (const DrawItem& item : list.items) {
        const bool blend = !settings.coverageOnly &&
                           (item.fade < 1.0f || scene.material(item.part.material).alphaMode == AlphaMode::Blend);
        (blend ? blended : opaque).push_back(&item);
    }
    std::sort(opaque.begin(), opaque.end(), [](auto* a, auto* b) { return a->viewDistance < b->viewDistance; });
    std::sort(blended.begin(), blended.end(), [](auto* a, auto* b) { return a->viewDistance > b->viewDistance; });

    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    for (const DrawItem* item : opaque) drawItem(scene, *item, view, settings);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied "over"
    glDepthMask(GL_FALSE);
    for (const DrawItem* item : blended) drawItem(scene, *item, view, settings);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glBindVertexArray(0);
}

} // namespace arcomp
