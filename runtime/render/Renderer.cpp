#include "runtime/render/Renderer.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <span>

namespace arcomp {

using namespace gl;

namespace {

const char* const kMeshShader = R"(
// One source for all four shading levels; SHADING picks how much of glTF's
// metallic-roughness model a level evaluates. Cheapest first, as the frame
// budget controller (DESIGN.md, section 3) steps through them:
//   0 Unlit:   base colour + emission, no light (also every KHR_materials_unlit
//              material, without its emission, and coverage-only passes).
//   1 Flat:    as Gouraud, but one light per face: the provoking vertex's,
//              not interpolated (GL's flat shading model). The derivative
//              face normal with the BRDF per pixel looked better but cost
//              twice Gouraud on llvmpipe, out of the controller's order.
//   2 Gouraud: the BRDF's direct light and the irradiance ambient per vertex,
//              with the material's factors; textures still per pixel. No
//              normal map, no specular image-based light.
//   At these two levels the irradiance also stands in for the reflected
//   environment (F0 * E / pi, what a fully rough mirror would reflect), so
//   that metals, which have no diffuse colour, do not turn black there.
//   3 Phong:   everything per pixel: normal map, direct light, diffuse
//              irradiance + prefiltered specular (split sum) with the
//              energy rough surfaces lose to multiple scattering given
//              back, occlusion on the indirect light.
// Emission is added at every level. Lighting is in linear light; the output
// is premultiplied and sRGB-encoded (Renderer.hpp).
// SKINNED (with MAX_JOINTS) compiles the variant for skinned meshes: the
// vertex is posed by its joints before anything else, so unskinned draws
// run the shader without it. UNTEXTURED compiles the variant for materials
// with no texture in any slot: a uniform test per slot still costs llvmpipe
// about a third of a lit pixel.
#ifdef VERTEX
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aTexcoord0;
layout(location = 3) in vec2 aTexcoord1;
layout(location = 4) in vec4 aTangent;
layout(location = 5) in vec4 aColor;
#ifdef SKINNED
layout(location = 6) in vec4 aJoints;   // indices into uJointMatrices, as floats (exact below 2^24)
layout(location = 7) in vec4 aWeights;  // summing to 1
// Joint matrices (Scene::jointMatrices) are affine: only their top three
// rows are kept, as the columns of a mat3x4, so that a joint takes three
// uniform vectors rather than four (Skin.hpp, kMaxJointsPerDraw).
// vec4(p, 1.0) * uJointMatrices[j] is (jointMatrix * vec4(p, 1.0)).xyz.
uniform mat3x4 uJointMatrices[MAX_JOINTS];
#endif
#define VARYING out
#else
#define VARYING in
#endif
#if SHADING == 1
#define LIGHT_VARYING flat VARYING
#else
#define LIGHT_VARYING VARYING
#endif
VARYING vec3 vWorld;
VARYING vec3 vNormal;
VARYING vec4 vTangent;
VARYING vec2 vTexcoord0;
VARYING vec2 vTexcoord1;
VARYING vec4 vColor;
LIGHT_VARYING vec3 vDiffuseLight;   // Flat, Gouraud: what multiplies the diffuse colour
LIGHT_VARYING vec3 vSpecularLight;  // Flat, Gouraud: the direct highlight
LIGHT_VARYING vec3 vBackDiffuseLight, vBackSpecularLight;  // the same for back faces of double-sided ones

uniform mat4 uModel;
uniform mat4 uViewProjection;
uniform mat3 uNormalMatrix;
uniform vec3 uEye;
uniform vec3 uLightDirection;  // towards the light
uniform vec3 uLightRadiance;   // colour * intensity
uniform mat4 uIrradiance[3];   // E(n)/pi per channel (ImageBasedLight.hpp), times the environment's intensity
uniform float uEnvironmentIntensity;
uniform float uSpecularLevels;
uniform sampler2D uSpecularEnvironment;
uniform sampler2D uSplitSum;

uniform vec4 uBaseColor;
uniform float uMetallic;
uniform float uRoughness;
uniform vec3 uEmissive;  // factor * strength
uniform float uNormalScale;
uniform float uOcclusionStrength;
uniform int uAlphaMode;
uniform float uAlphaCutoff;
uniform float uFade;
uniform int uDoubleSided;
uniform int uHasTangents;
// Texture slots: base colour, metallic-roughness, normal, occlusion,
// emissive. uTexCoord: which TEXCOORD set, -1 when the slot is empty.
uniform int uTexCoord[5];
#ifdef UNTEXTURED
#define HAS_SLOT(slot) false
#else
#define HAS_SLOT(slot) (uTexCoord[slot] >= 0)
#endif
uniform mat3 uUvTransform[5];
uniform sampler2D uBaseColorTexture;
uniform sampler2D uMetallicRoughnessTexture;
uniform sampler2D uNormalTexture;
uniform sampler2D uOcclusionTexture;
uniform sampler2D uEmissiveTexture;

const float PI = 3.14159265358979;

// glTF 2.0 Appendix B: the specular BRDF is F * D * V with GGX's
// (Trowbridge-Reitz) D, Smith's height-correlated visibility V and Schlick's
// Fresnel F; the diffuse one (1 - F) * c_diff / pi, where
// c_diff = base * (1 - metallic), F0 = mix(0.04, base, metallic) and
// alpha = roughness^2. Returns, for the directional light, the factor on
// c_diff and the specular radiance separately, so Gouraud can multiply a
// per-pixel texture afterwards.
void directLight(vec3 n, vec3 v, vec3 f0, float roughness, out vec3 diffuse, out vec3 specular) {
    vec3 l = uLightDirection;
    float nl = dot(n, l);
    if (nl <= 0.0) {
        diffuse = vec3(0.0);
        specular = vec3(0.0);
        return;
    }
    vec3 h = normalize(l + v);
    float nv = max(dot(n, v), 1e-4);
    float nh = max(dot(n, h), 0.0);
    float vh = max(dot(v, h), 0.0);
    // A perfect mirror reflects a directional light into one direction no
    // pixel sees; a floor on roughness keeps the highlight visible and finite.
    float alpha = max(roughness, 0.05);
    alpha *= alpha;
    float a2 = alpha * alpha;
    float d = nh * nh * (a2 - 1.0) + 1.0;
    float D = a2 / (PI * d * d);
    float V = 0.5 / (nl * sqrt(nv * nv * (1.0 - a2) + a2) + nv * sqrt(nl * nl * (1.0 - a2) + a2));
    float m = 1.0 - vh, m2 = m * m;  // (1 - v.h)^5 by products: pow is a log and an exp on llvmpipe
    vec3 F = f0 + (1.0 - f0) * (m2 * m2 * m);
    diffuse = (1.0 - F) / PI * uLightRadiance * nl;
    specular = F * D * V * uLightRadiance * nl;
}

// Single-scattering GGX loses the light that bounces between microfacets
// before it leaves: a rough metal seen head-on keeps a third of it and
// looks dark and dull. What is lost, 1 - (A + B) with (A, B) the split
// sum's environment BRDF, comes back as multiple scattering tinted by the
// average Fresnel f0 + (1 - f0) / 21 (Fdez-Aguera 2019, "A Multiple-
// Scattering Microfacet Model for Real-Time Image-Based Lighting"): the
// share of the irradiance that the multiple scattering reflects, given
// the single scattering's f0 * A + B.
vec3 multipleScattering(vec3 f0, vec3 single, float lost) {
    vec3 averageFresnel = f0 + (1.0 - f0) / 21.0;
    return lost * single * averageFresnel / (1.0 - lost * averageFresnel);
}

vec3 diffuseIrradiance(vec3 n) {
    vec4 n4 = vec4(n, 1.0);
    return max(vec3(dot(n4, uIrradiance[0] * n4), dot(n4, uIrradiance[1] * n4), dot(n4, uIrradiance[2] * n4)), 0.0);
}

#ifdef VERTEX
void main() {
    vec3 position = aPosition, normal = aNormal, tangent = aTangent.xyz;
#ifdef SKINNED
    // glTF 2.0, 3.7.3.3: the skin matrix is sum_i weight_i * jointMatrix[joint_i].
    // Normals and tangents go through it too, as three.js does (exact for
    // rigid joints; the normal matrix below handles the node's scale).
    mat3x4 skin = aWeights.x * uJointMatrices[int(aJoints.x)] + aWeights.y * uJointMatrices[int(aJoints.y)] +
                  aWeights.z * uJointMatrices[int(aJoints.z)] + aWeights.w * uJointMatrices[int(aJoints.w)];
    position = vec4(position, 1.0) * skin;
    normal = vec4(normal, 0.0) * skin;
    tangent = vec4(tangent, 0.0) * skin;
#endif
    vec4 world = uModel * vec4(position, 1.0);
    vWorld = world.xyz;
    vNormal = normalize(uNormalMatrix * normal);
    vTangent = vec4(mat3(uModel) * tangent, aTangent.w);
    vTexcoord0 = aTexcoord0;
    vTexcoord1 = aTexcoord1;
    vColor = aColor;
#if SHADING == 1 || SHADING == 2
    vec3 v = normalize(uEye - vWorld);
    vec3 base = uBaseColor.rgb * aColor.rgb;
    vec3 f0 = mix(vec3(0.04), base, uMetallic);
    directLight(vNormal, v, f0, uRoughness, vDiffuseLight, vSpecularLight);
    vec3 ambient = diffuseIrradiance(vNormal);
    vDiffuseLight += ambient;
    vSpecularLight += f0 * ambient;
    if (uDoubleSided != 0) {
        directLight(-vNormal, v, f0, uRoughness, vBackDiffuseLight, vBackSpecularLight);
        vec3 backAmbient = diffuseIrradiance(-vNormal);
        vBackDiffuseLight += backAmbient;
        vBackSpecularLight += f0 * backAmbient;
    } else {
        vBackDiffuseLight = vDiffuseLight;
        vBackSpecularLight = vSpecularLight;
    }
#else
    vDiffuseLight = vSpecularLight = vBackDiffuseLight = vBackSpecularLight = vec3(0.0);
#endif
    gl_Position = uViewProjection * world;
}
#else
out vec4 fragColor;

// A slot's coordinates: its TEXCOORD set through its KHR_texture_transform.
vec2 slotUv(int slot) {
    vec2 uv = uTexCoord[slot] == 1 ? vTexcoord1 : vTexcoord0;
    return (uUvTransform[slot] * vec3(uv, 1.0)).xy;
}

// The sRGB transfer function (IEC 61966-2-1), as three.js's sRGB output.
vec3 srgbEncode(vec3 c) {
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

// Equirectangular lookup, laid out as Environment.hpp says.
vec2 environmentUv(vec3 d) {
    return vec2(atan(d.z, d.x) / (2.0 * PI) + 0.5, 0.5 - asin(clamp(d.y, -1.0, 1.0)) / PI);
}

// The surface normal at this pixel for the top level: the interpolated one
// (flipped on back faces of double-sided materials), perturbed by the normal
// map in the frame of the vertex tangent (w: the bitangent's sign), or,
// without tangents, of a frame from the screen-space derivatives of position
// and texture coordinates (as glTF asks for MikkTSpace there, this is an
// approximation that agrees on flat, unmirrored mappings).
vec3 shadingNormal(vec3 n) {
    if (!HAS_SLOT(2)) return n;
    vec2 uv = slotUv(2);
    vec3 t, b;
    if (uHasTangents != 0) {
        t = normalize(vTangent.xyz - n * dot(n, vTangent.xyz));
        b = cross(n, t) * (vTangent.w < 0.0 ? -1.0 : 1.0);
    } else {
        // Solve dp = t du + b dv over the pixel's footprint for t; then b as
        // a tangent with w = +1 would give it.
        vec3 dp1 = dFdx(vWorld), dp2 = dFdy(vWorld);
        vec2 duv1 = dFdx(uv), duv2 = dFdy(uv);
        float det = duv1.x * duv2.y - duv2.x * duv1.y;
        t = (dp1 * duv2.y - dp2 * duv1.y) * (det < 0.0 ? -1.0 : 1.0);
        t -= n * dot(n, t);
        t = dot(t, t) > 1e-20 ? normalize(t) : normalize(cross(n, abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
        b = cross(n, t);
    }
    // n came reversed on a back face, and b with it (b = n x t); reversing
    // t too turns the whole frame over, so the map's relief reads the same
    // from both sides.
    if (!gl_FrontFacing) t = -t;
    vec3 m = texture(uNormalTexture, uv).xyz * 2.0 - 1.0;
    m.xy *= uNormalScale;
    return normalize(mat3(t, b, n) * m);
}

void main() {
    vec4 base = uBaseColor * vColor;
    if (HAS_SLOT(0)) base *= texture(uBaseColorTexture, slotUv(0));  // decoded from sRGB by the format
    if (uAlphaMode == 1 && base.a < uAlphaCutoff) discard;
    float alpha = (uAlphaMode == 2 ? base.a : 1.0) * uFade;
    vec3 emission = uEmissive;
    if (HAS_SLOT(4)) emission *= texture(uEmissiveTexture, slotUv(4)).rgb;

#if SHADING == 0
    vec3 lit = base.rgb;
#else
    float metallic = uMetallic, roughness = uRoughness;
    if (HAS_SLOT(1)) {
        vec4 mr = texture(uMetallicRoughnessTexture, slotUv(1));
        roughness *= mr.g;
        metallic *= mr.b;
    }
    vec3 diffuseColor = base.rgb * (1.0 - metallic);
    vec3 f0 = mix(vec3(0.04), base.rgb, metallic);
    vec3 v = normalize(uEye - vWorld);
#if SHADING == 1 || SHADING == 2
    vec3 lit = gl_FrontFacing ? diffuseColor * vDiffuseLight + vSpecularLight
                              : diffuseColor * vBackDiffuseLight + vBackSpecularLight;
#else
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;
    n = shadingNormal(n);
    vec3 diffuse, specular;
    directLight(n, v, f0, roughness, diffuse, specular);
    float nv = clamp(dot(n, v), 1e-4, 1.0);
    float occlusion = 1.0;
    if (HAS_SLOT(3)) occlusion = 1.0 + uOcclusionStrength * (texture(uOcclusionTexture, slotUv(3)).r - 1.0);
    // Karis 2013 split sum: prefiltered radiance times F0 * scale + bias.
    vec2 scaleBias = texture(uSplitSum, vec2(nv, roughness)).rg;
    vec3 r = reflect(-v, n);
    vec3 prefiltered = textureLod(uSpecularEnvironment, environmentUv(r), roughness * (uSpecularLevels - 1.0)).rgb;
    float singleAlbedo = scaleBias.x + scaleBias.y;
    vec3 single = f0 * scaleBias.x + scaleBias.y;
    // What the dielectric layer (F0 0.04) reflects, once or more, does not
    // reach its diffuse base.
    float dielectricSingle = 0.04 * scaleBias.x + scaleBias.y;
    float dielectricMultiple = multipleScattering(vec3(0.04), vec3(dielectricSingle), 1.0 - singleAlbedo).x;
    vec3 irradiance = diffuseIrradiance(n);
    vec3 indirect = diffuseColor * (1.0 - dielectricSingle - dielectricMultiple) * irradiance
                  + prefiltered * uEnvironmentIntensity * single
                  + multipleScattering(f0, single, 1.0 - singleAlbedo) * irradiance;
    // The directional light's highlight loses the same share; it is scaled
    // back up by 1 + F0 (1 / E - 1), E the single-scattering albedo (Turquin
    // 2019, "Practical multiple scattering compensation for microfacet models").
    specular *= 1.0 + f0 * (1.0 / max(singleAlbedo, 1e-3) - 1.0);
    vec3 lit = diffuse * diffuseColor + specular + occlusion * indirect;
#endif
#endif
    vec3 encoded = srgbEncode(clamp(lit + emission, 0.0, 1.0));
    fragColor = vec4(encoded * alpha, alpha);
}
#endif
)";

// glTF's sampler enums to GL's.
GLint glWrap(TextureWrap w) {
    switch (w) {
    case TextureWrap::ClampToEdge: return GL_CLAMP_TO_EDGE;
    case TextureWrap::MirroredRepeat: return GL_MIRRORED_REPEAT;
    case TextureWrap::Repeat: break;
    }
    return GL_REPEAT;
}
GLint glFilter(TextureFilter f) {
    switch (f) {
    case TextureFilter::Nearest: return GL_NEAREST;
    case TextureFilter::Linear: return GL_LINEAR;
    case TextureFilter::NearestMipmapNearest: return GL_NEAREST_MIPMAP_NEAREST;
    case TextureFilter::LinearMipmapNearest: return GL_LINEAR_MIPMAP_NEAREST;
    case TextureFilter::NearestMipmapLinear: return GL_NEAREST_MIPMAP_LINEAR;
    case TextureFilter::LinearMipmapLinear: break;
    }
    return GL_LINEAR_MIPMAP_LINEAR;
}
bool usesMipmaps(TextureFilter f) { return f != TextureFilter::Nearest && f != TextureFilter::Linear; }

// Texture units, one per material slot in Material::textures() order, then
// the environment's two.
constexpr int kSlotCount = 5;
constexpr GLint kSpecularUnit = kSlotCount, kSplitSumUnit = kSlotCount + 1;

// The environment-free half of image-based lighting, and the built-in
// environment's other half: the same for every Renderer, so worked out once
// per process.
const SplitSumTable& sharedSplitSum() {
    static const SplitSumTable table = splitSumTable();
    return table;
}
const ImageBasedLight& neutralLight() {
    static const ImageBasedLight light = prefilterEnvironment(neutralEnvironment());
    return light;
}

}  // namespace

// Lighting's uniforms are read only where a level lights, and the compiler
// drops them elsewhere: those may be -1, as may the texture slots' in the
// untextured variant. The rest every level reads.
Renderer::MeshProgram::MeshProgram(Shading shading, bool skinned, bool textured)
    : program(kMeshShader,
              "#define SHADING " + std::to_string(static_cast<int>(shading)) + "\n" +
                  (skinned ? "#define SKINNED\n#define MAX_JOINTS " + std::to_string(kMaxJointsPerDraw) + "\n" : "") +
                  (textured ? "" : "#define UNTEXTURED\n")),
      model(program.requiredLocation("uModel")), viewProjection(program.requiredLocation("uViewProjection")),
      normalMatrix(program.location("uNormalMatrix")), eye(program.location("uEye")),
      lightDirection(program.location("uLightDirection")), lightRadiance(program.location("uLightRadiance")),
      irradiance(program.location("uIrradiance")), environmentIntensity(program.location("uEnvironmentIntensity")),
      specularLevels(program.location("uSpecularLevels")),
      specularEnvironment(program.location("uSpecularEnvironment")), splitSum(program.location("uSplitSum")),
      baseColor(program.requiredLocation("uBaseColor")), metallic(program.location("uMetallic")),
      roughness(program.location("uRoughness")), emissive(program.requiredLocation("uEmissive")),
      normalScale(program.location("uNormalScale")), occlusionStrength(program.location("uOcclusionStrength")),
      alphaMode(program.requiredLocation("uAlphaMode")), alphaCutoff(program.requiredLocation("uAlphaCutoff")),
      fade(program.requiredLocation("uFade")), doubleSided(program.location("uDoubleSided")),
      hasTangents(program.location("uHasTangents")),
      texCoord(textured ? program.requiredLocation("uTexCoord") : program.location("uTexCoord")),
      uvTransform(textured ? program.requiredLocation("uUvTransform") : program.location("uUvTransform")),
      jointMatrices(skinned ? program.requiredLocation("uJointMatrices") : -1) {
    const char* const samplers[kSlotCount] = {"uBaseColorTexture", "uMetallicRoughnessTexture", "uNormalTexture",
                                              "uOcclusionTexture", "uEmissiveTexture"};
    // Each sampler uniform keeps its unit for the program's life.
    program.use();
    for (int slot = 0; slot < kSlotCount; ++slot) glUniform1i(program.location(samplers[slot]), slot);
    glUniform1i(specularEnvironment, kSpecularUnit);
    glUniform1i(splitSum, kSplitSumUnit);
}

Renderer::Renderer() {
    for (int s = 0; s < kShadingCount; ++s) program(static_cast<Shading>(s), false, true);
    const SplitSumTable& table = sharedSplitSum();
    splitSum_ = GlTexture::generate();
    glBindTexture(GL_TEXTURE_2D, splitSum_.get());
    // RG16F: filterable on ES 3.0 as on desktop (32-bit floats are not).
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RG16F, table.size, table.size, 0, GL_RG, GL_FLOAT, table.scaleBias.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    setEnvironment(neutralLight());
}

void Renderer::setEnvironment(const ImageBasedLight& light) {
    irradiance_ = light.irradiance;
    specularLevels_ = static_cast<int>(light.specular.size());
    specular_ = GlTexture::generate();
    glBindTexture(GL_TEXTURE_2D, specular_.get());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    // RGB9_E5: high dynamic range and filterable on ES 3.0 without an
    // extension; each roughness is one mip level, read with textureLod.
    for (int level = 0; level < specularLevels_; ++level) {
        const Environment& e = light.specular[static_cast<std::size_t>(level)];
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGB9_E5, e.width, e.height, 0, GL_RGB, GL_FLOAT, e.radiance.data());
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, specularLevels_ - 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);  // azimuth goes round
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

const Renderer::MeshProgram& Renderer::program(Shading shading, bool skinned, bool textured) {
    const std::size_t variant = static_cast<std::size_t>(shading) + kShadingCount * (2u * skinned + textured);
    auto& slot = programs_[variant];
    // Variants other than the textured unskinned ones are compiled on their
    // first draw: a scene without skins never pays for them.
    if (!slot) slot.emplace(shading, skinned, textured);
    return *slot;
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
    const std::size_t n = g.positions.size();
    // Interleaved, one buffer and one fetch stream; attributes the geometry
    // lacks take no space and are read as constants (see drawItem).
    const bool uv0 = g.texcoords.size() == n, uv1 = g.texcoords1.size() == n;
    gpu.hasTangents = g.tangents.size() == n && n > 0;
    gpu.hasColors = g.colors.size() == n && n > 0;
    gpu.hasSkinInfluences = g.hasSkinInfluences();
    const std::array<std::pair<bool, int>, 8> attributes{{{true, 3},
                                                          {true, 3},
                                                          {uv0, 2},
                                                          {uv1, 2},
                                                          {gpu.hasTangents, 4},
                                                          {gpu.hasColors, 4},
                                                          {gpu.hasSkinInfluences, 4},
                                                          {gpu.hasSkinInfluences, 4}}};
    int floatsPerVertex = 0;
    for (const auto& [present, size] : attributes) floatsPerVertex += present ? size : 0;
    std::vector<float> vertices;
    vertices.reserve(n * static_cast<std::size_t>(floatsPerVertex));
    for (std::size_t i = 0; i < n; ++i) {
        vertices.insert(vertices.end(), {g.positions[i].x, g.positions[i].y, g.positions[i].z, g.normals[i].x,
                                         g.normals[i].y, g.normals[i].z});
        if (uv0) vertices.insert(vertices.end(), {g.texcoords[i].x, g.texcoords[i].y});
        if (uv1) vertices.insert(vertices.end(), {g.texcoords1[i].x, g.texcoords1[i].y});
        if (gpu.hasTangents)
            vertices.insert(vertices.end(), {g.tangents[i].x, g.tangents[i].y, g.tangents[i].z, g.tangents[i].w});
        if (gpu.hasColors)
            vertices.insert(vertices.end(), {g.colors[i].r, g.colors[i].g, g.colors[i].b, g.colors[i].a});
        if (gpu.hasSkinInfluences) {
            const glm::vec4 joints(g.joints[i]);
            vertices.insert(vertices.end(), {joints.x, joints.y, joints.z, joints.w, g.weights[i].x, g.weights[i].y,
                                             g.weights[i].z, g.weights[i].w});
        }
    }
    gpu.vao = GlVertexArray::generate();
    glBindVertexArray(gpu.vao.get());
    gpu.vertices = GlBuffer::generate();
    glBindBuffer(GL_ARRAY_BUFFER, gpu.vertices.get());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(float)), vertices.data(),
                 GL_STATIC_DRAW);
    gpu.indices = GlBuffer::generate();
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.indices.get());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(g.indices.size() * sizeof(std::uint32_t)),
                 g.indices.data(), GL_STATIC_DRAW);
    const auto stride = static_cast<GLsizei>(static_cast<std::size_t>(floatsPerVertex) * sizeof(float));
    std::size_t offset = 0;
    for (GLuint a = 0; a < attributes.size(); ++a) {
        const auto [present, size] = attributes[a];
        if (!present) continue;
        glEnableVertexAttribArray(a);
        glVertexAttribPointer(a, size, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offset * sizeof(float)));
        offset += static_cast<std::size_t>(size);
    }
    glBindVertexArray(0);
    gpu.indexCount = static_cast<GLsizei>(g.indices.size());
    return gpu;
}

GLuint Renderer::texture(const Scene& scene, const TextureRef& ref, bool srgb) {
    if (!ref.present() || static_cast<std::size_t>(ref.image) >= scene.images().size()) return 0;
    const Sampler& s = ref.sampler;
    const TextureKey key{ref.image, srgb, s.magFilter, s.minFilter, s.wrapS, s.wrapT};
    GlTexture& t = textures_[key];
    if (t) return t.get();
    const Image& img = scene.images()[static_cast<std::size_t>(ref.image)];
    if (img.width <= 0 || img.height <= 0 || img.rgba.size() != static_cast<std::size_t>(img.width * img.height * 4))
        return 0;  // an empty slot draws as if absent rather than reading past the pixels
    t = GlTexture::generate();
    glBindTexture(GL_TEXTURE_2D, t.get());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    // Colour slots are sRGB-encoded (glTF 3.9.2): the format decodes them
    // before filtering, as it must.
    glTexImage2D(GL_TEXTURE_2D, 0, srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, img.width, img.height, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, img.rgba.data());
    if (usesMipmaps(s.minFilter)) glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, glFilter(s.minFilter));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER,
                    s.magFilter == TextureFilter::Nearest ? GL_NEAREST : GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, glWrap(s.wrapS));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, glWrap(s.wrapT));
    return t.get();
}

void Renderer::drawItem(const Scene& scene, const DrawItem& item, const View& view, const RenderSettings& settings) {
    const Material& m = scene.material(item.part.material);
    const Shading shading = m.unlit || settings.coverageOnly ? Shading::Unlit : item.shading;
    const GpuGeometry& g = geometry(scene, item.part.geometry);
    const bool skinned = item.part.skin != kNoSkin && g.hasSkinInfluences && item.part.skin < scene.skinCount();
    const auto slots = m.textures();
    std::array<GLuint, kSlotCount> textures{};
    for (int slot = 0; slot < kSlotCount; ++slot)  // base colour and emission are colours (sRGB); the rest are data
        textures[static_cast<std::size_t>(slot)] =
            texture(scene, *slots[static_cast<std::size_t>(slot)], slot == 0 || slot == 4);
    const bool textured = std::any_of(textures.begin(), textures.end(), [](GLuint t) { return t != 0; });
    const MeshProgram& p = program(shading, skinned, textured);
    p.program.use();
    const glm::mat4& model = item.model ? *item.model : scene.world(item.node);
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(model)));
    const glm::mat4 viewProjection = view.viewProjection();
    glUniformMatrix4fv(p.model, 1, GL_FALSE, glm::value_ptr(model));
    glUniformMatrix4fv(p.viewProjection, 1, GL_FALSE, glm::value_ptr(viewProjection));
    glUniformMatrix3fv(p.normalMatrix, 1, GL_FALSE, glm::value_ptr(normalMatrix));
    glUniform3f(p.eye, view.eye.x, view.eye.y, view.eye.z);
    const glm::vec3 l = glm::normalize(settings.lightDirection);
    glUniform3f(p.lightDirection, l.x, l.y, l.z);
    const glm::vec3 light = settings.lightColor * settings.lightIntensity;
    glUniform3f(p.lightRadiance, light.r, light.g, light.b);
    std::array<glm::mat4, 3> irradiance = irradiance_;
    for (glm::mat4& channel : irradiance) channel *= settings.environmentIntensity;
    glUniformMatrix4fv(p.irradiance, 3, GL_FALSE, glm::value_ptr(irradiance[0]));
    glUniform1f(p.environmentIntensity, settings.environmentIntensity);
    glUniform1f(p.specularLevels, static_cast<float>(specularLevels_));

    const glm::vec4 base = m.baseColor * item.tint;
    glUniform4f(p.baseColor, base.r, base.g, base.b, base.a);
    glUniform1f(p.metallic, m.metallic);
    glUniform1f(p.roughness, m.roughness);
    // KHR_materials_unlit draws the base colour alone: its emission is
    // ignored, as the extension says and three.js does.
    const glm::vec3 emissive = settings.coverageOnly || m.unlit ? glm::vec3(0.0f) : m.emissive * m.emissiveStrength;
    glUniform3f(p.emissive, emissive.r, emissive.g, emissive.b);
    glUniform1f(p.normalScale, m.normalScale);
    glUniform1f(p.occlusionStrength, m.occlusionStrength);
    glUniform1i(p.alphaMode, static_cast<int>(m.alphaMode));
    glUniform1f(p.alphaCutoff, m.alphaCutoff);
    glUniform1f(p.fade, item.fade);
    glUniform1i(p.doubleSided, m.doubleSided ? 1 : 0);

    std::array<GLint, kSlotCount> texCoord{};
    std::array<glm::mat3, kSlotCount> uvTransform{};
    for (int slot = 0; slot < kSlotCount; ++slot) {
        const TextureRef& ref = *slots[static_cast<std::size_t>(slot)];
        const GLuint tex = textures[static_cast<std::size_t>(slot)];
        texCoord[static_cast<std::size_t>(slot)] = tex ? std::clamp(ref.texCoord, 0, 1) : -1;
        uvTransform[static_cast<std::size_t>(slot)] = ref.transform.matrix();
        glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + slot));
        glBindTexture(GL_TEXTURE_2D, tex);
    }
    glUniform1iv(p.texCoord, kSlotCount, texCoord.data());
    glUniformMatrix3fv(p.uvTransform, kSlotCount, GL_FALSE, glm::value_ptr(uvTransform[0]));
    glActiveTexture(GL_TEXTURE0 + kSpecularUnit);
    glBindTexture(GL_TEXTURE_2D, specular_.get());
    glActiveTexture(GL_TEXTURE0 + kSplitSumUnit);
    glBindTexture(GL_TEXTURE_2D, splitSum_.get());
    glActiveTexture(GL_TEXTURE0);

    if (skinned) {
        // The top three rows of each joint matrix, as the shader's mat3x4
        // columns: the first 12 floats of its transpose.
        const std::span<const glm::mat4> joints = scene.jointMatrices(item.part.skin);
        const std::size_t count = std::min(joints.size(), kMaxJointsPerDraw);
        jointRows_.resize(count * 12);
        for (std::size_t j = 0; j < count; ++j) {
            const glm::mat4 rows = glm::transpose(joints[j]);
            std::copy_n(glm::value_ptr(rows), 12, jointRows_.data() + j * 12);
        }
        glUniformMatrix3x4fv(p.jointMatrices, static_cast<GLsizei>(count), GL_FALSE, jointRows_.data());
    }

    if (m.doubleSided)
        glDisable(GL_CULL_FACE);
    else
        glEnable(GL_CULL_FACE);
    glUniform1i(p.hasTangents, g.hasTangents ? 1 : 0);
    // What an absent attribute reads: generic values are context state, not
    // the vertex array's, so they are set for every draw.
    glVertexAttrib4f(2, 0.0f, 0.0f, 0.0f, 1.0f);
    glVertexAttrib4f(3, 0.0f, 0.0f, 0.0f, 1.0f);
    glVertexAttrib4f(4, 1.0f, 0.0f, 0.0f, 1.0f);
    glVertexAttrib4f(5, 1.0f, 1.0f, 1.0f, 1.0f);
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

}  // namespace arcomp
