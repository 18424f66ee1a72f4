// glTF as pipelines ship it: Draco and meshopt geometry, quantized
// attributes and WebP textures decode to the source within each
// attribute's quantization step; what arcomp cannot decode is refused, or
// drawn without, by the extension's name.

#include "graph/io/GltfWriter.hpp"
#include "graph/io/ModelLoader.hpp"

#include "../support/QuadGltf.hpp"
#include "../support/Shell.hpp"
#include "../support/TempDir.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <webp/encode.h>

#include <cmath>
#include <fstream>
#include <limits>

using namespace arcomp;
using arcomp::test::TempDir;
namespace fs = std::filesystem;

namespace {

// The source every compressed copy is made from: a UV sphere with normals
// and texture coordinates, off the origin so that positions are not
// symmetric about it.
Geometry sourceSphere() {
    Geometry g = makeUvSphere(0.8f, 24, 12);
    for (glm::vec3& p : g.positions) p += glm::vec3(1.5f, 0.25f, -0.5f);
    return g;
}

struct Corners {
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> texcoords;
    std::size_t triangles = 0;
};

// Every primitive of a parsed model in world space, with its material's
// texture transform applied to the texture coordinates (gltfpack
// quantizes them through KHR_texture_transform).
Corners worldCorners(const ParsedModel& model) {
    Corners out;
    std::vector<glm::mat4> world(model.nodes.size());
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        const ModelNode& node = model.nodes[n];
        world[n] = node.parent < 0 ? node.local : world[static_cast<std::size_t>(node.parent)] * node.local;
        for (const MeshPart& part : node.parts) {
            const Geometry& g = model.geometries[part.geometry];
            const TextureTransform& uv = model.materials[part.material].baseColorTexture.transform;
            const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(world[n])));
            for (std::size_t v = 0; v < g.positions.size(); ++v) {
                out.positions.push_back(glm::vec3(world[n] * glm::vec4(g.positions[v], 1.0f)));
                out.normals.push_back(glm::normalize(normalMatrix * g.normals[v]));
                const glm::vec2 t = g.texcoords.empty() ? glm::vec2(0.0f) : g.texcoords[v];
                const float c = std::cos(uv.rotation), s = std::sin(uv.rotation);
                const glm::vec2 scaled = t * uv.scale;
                out.texcoords.push_back(uv.offset +
                                        glm::vec2(c * scaled.x + s * scaled.y, -s * scaled.x + c * scaled.y));
            }
            out.triangles += g.triangleCount();
        }
    }
    return out;
}

struct Steps {
    float position, normal, texcoord;
};

// Each source vertex has a decoded vertex within one step of every
// attribute, and each decoded vertex a source one: the encoders reorder
// and merge vertices, so vertices are matched by position.
void expectSameVertices(const Geometry& source, const Corners& decoded, Steps steps) {
    ASSERT_FALSE(decoded.positions.empty());
    const auto nearest = [](const glm::vec3& p, const std::vector<glm::vec3>& in) {
        std::size_t best = 0;
        float bestDistance = std::numeric_limits<float>::max();
        for (std::size_t i = 0; i < in.size(); ++i)
            if (const float d = glm::length(in[i] - p); d < bestDistance) {
                bestDistance = d;
                best = i;
            }
        return best;
    };
    float worstPosition = 0.0f, worstNormal = 0.0f, worstTexcoord = 0.0f;
    for (std::size_t v = 0; v < source.positions.size(); ++v) {
        const std::size_t d = nearest(source.positions[v], decoded.positions);
        worstPosition = std::max(worstPosition, glm::length(decoded.positions[d] - source.positions[v]));
    }
    for (std::size_t d = 0; d < decoded.positions.size(); ++d) {
        // The sphere's seam and poles repeat a position with other normals
        // and coordinates: the closest attributes among the source vertices
        // at that position count.
        float normal = std::numeric_limits<float>::max(), texcoord = normal, position = normal;
        for (std::size_t v = 0; v < source.positions.size(); ++v) {
            if (glm::length(source.positions[v] - decoded.positions[d]) > steps.position) continue;
            position = std::min(position, glm::length(source.positions[v] - decoded.positions[d]));
            normal = std::min(normal, glm::length(source.normals[v] - decoded.normals[d]));
            texcoord = std::min(texcoord, glm::length(source.texcoords[v] - decoded.texcoords[d]));
        }
        ASSERT_LT(position, steps.position) << "decoded vertex " << d << " matches no source vertex";
        worstNormal = std::max(worstNormal, normal);
        worstTexcoord = std::max(worstTexcoord, texcoord);
    }
    EXPECT_LE(worstPosition, steps.position);
    EXPECT_LE(worstNormal, steps.normal);
    EXPECT_LE(worstTexcoord, steps.texcoord);
}

// A step of `bits` over a range: what one quantization level spans, times
// the components it may err in (a vector's length adds them up).
float step(float range, int bits, int components) {
    return range / static_cast<float>((1 << bits) - 1) * std::sqrt(static_cast<float>(components));
}

std::string writeSource(const Geometry& g) {
    GltfWriter w;
    const int position =
        w.accessor(g.positions.data(), g.positions.size(), "VEC3", GltfWriter::kFloat, {.bounds = true});
    const int normal = w.accessor(g.normals.data(), g.normals.size(), "VEC3", GltfWriter::kFloat);
    const int uv = w.accessor(g.texcoords.data(), g.texcoords.size(), "VEC2", GltfWriter::kFloat);
    const int indices = w.accessor(g.indices.data(), g.indices.size(), "SCALAR", GltfWriter::kUnsignedInt);
    GltfWriter::add(w.meshes, R"({"primitives": [{"attributes": {"POSITION": )" + std::to_string(position) +
                                  R"(, "NORMAL": )" + std::to_string(normal) + R"(, "TEXCOORD_0": )" +
                                  std::to_string(uv) + R"(}, "indices": )" + std::to_string(indices) + "}]}");
    w.sceneNodes.push_back(GltfWriter::add(w.nodes, R"({"mesh": 0})"));
    return w.text();
}

// The same with a textured material: gltfpack drops texture coordinates
// that no texture uses.
std::string writeTexturedSource(const Geometry& g) {
    std::string text = writeSource(g);
    text.insert(text.rfind('}'), R"(, "images": [{"uri": "data:image/png;base64,)" +
                                     std::string(arcomp::test::kTinyPng) +
                                     R"("}], "textures": [{"source": 0}],
        "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}])");
    text.replace(text.find(R"("indices")"), 0, R"("material": 0, )");
    return text;
}

std::string writeDraco(const Geometry& g, bool sequential, int positionBits, int normalBits, int texcoordBits) {
    GltfWriter w;
    const std::string primitive = w.dracoPrimitive(
        g.positions.size(),
        {{.semantic = "POSITION", .data = &g.positions[0].x, .components = 3, .quantizationBits = positionBits},
         {.semantic = "NORMAL", .data = &g.normals[0].x, .components = 3, .quantizationBits = normalBits},
         {.semantic = "TEXCOORD_0", .data = &g.texcoords[0].x, .components = 2, .quantizationBits = texcoordBits}},
        g.indices, sequential);
    GltfWriter::add(w.meshes, R"({"primitives": [)" + primitive + "]}");
    w.sceneNodes.push_back(GltfWriter::add(w.nodes, R"({"mesh": 0})"));
    return w.text();
}

bool hasGltfpack() { return arcomp::test::shell("command -v gltfpack").code == 0; }

void expectRefused(const fs::path& file, const std::string& where, const std::string& part) {
    try {
        parseModel(file);
        ADD_FAILURE() << file << " loaded; expected a refusal at " << where;
    } catch (const ModelError& e) {
        EXPECT_EQ(e.where, where) << e.what();
        EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
}

}  // namespace

TEST(GltfCompressed, aDracoCopyDecodesToTheSourceWithinEachAttributesStep) {
    const Geometry source = sourceSphere();
    TempDir dir;
    for (const bool sequential : {true, false}) {
        SCOPED_TRACE(sequential ? "sequential" : "edgebreaker");
        const ParsedModel m =
            parseModel(dir.write(sequential ? "seq.gltf" : "eb.gltf", writeDraco(source, sequential, 14, 10, 12)));
        EXPECT_TRUE(m.notDrawn.empty());
        const Corners decoded = worldCorners(m);
        EXPECT_EQ(decoded.triangles, source.triangleCount());
        // Draco quantizes positions over the largest extent, texture
        // coordinates over theirs, normals octahedrally over [-1, 1] twice.
        expectSameVertices(source, decoded, {step(1.6f, 14, 3), step(4.0f, 10, 3), step(1.0f, 12, 2)});
    }
}

// gltfpack's three kinds of copy: meshopt with floats, quantized without
// compression (KHR_mesh_quantization), and both, as a web pipeline ships.
TEST(GltfCompressed, meshoptAndQuantizedCopiesDecodeToTheSourceWithinEachAttributesStep) {
    if (!hasGltfpack()) GTEST_SKIP() << "gltfpack is not installed (scripts/setup installs it)";
    const Geometry source = sourceSphere();
    TempDir dir;
    const fs::path src = dir.write("sphere.gltf", writeTexturedSource(source));
    struct Copy {
        const char* name;
        const char* options;
        bool meshopt, quantized;
    };
    for (const Copy& copy : {Copy{"meshopt.glb", "-c -noq", true, false}, Copy{"quantized.glb", "", false, true},
                             Copy{"both.glb", "-c", true, true}}) {
        SCOPED_TRACE(copy.name);
        const fs::path out = dir.path() / copy.name;
        const auto r = arcomp::test::shell("gltfpack -i " + src.string() + " -o " + out.string() + " " + copy.options);
        ASSERT_EQ(r.code, 0) << r.out;
        std::ifstream in(out, std::ios::binary);
        const std::string bytes{std::istreambuf_iterator<char>(in), {}};
        EXPECT_EQ(bytes.find("EXT_meshopt_compression") != std::string::npos, copy.meshopt);
        EXPECT_EQ(bytes.find("KHR_mesh_quantization") != std::string::npos, copy.quantized);
        const ParsedModel m = parseModel(out);
        EXPECT_TRUE(m.notDrawn.empty());
        const Corners decoded = worldCorners(m);
        EXPECT_EQ(decoded.triangles, source.triangleCount());
        // gltfpack's defaults: 14-bit positions over the mesh's extent,
        // 8-bit normals, 12-bit texture coordinates.
        const Steps steps =
            copy.quantized ? Steps{step(1.6f, 14, 3), step(2.0f, 8, 3), step(1.0f, 12, 2)} : Steps{1e-6f, 1e-6f, 1e-6f};
        expectSameVertices(source, decoded, steps);
    }
}

TEST(GltfCompressed, aWebpTextureDecodesToItsPixels) {
    const int size = 4;
    std::vector<std::uint8_t> rgba(size * size * 4);
    for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = static_cast<std::uint8_t>(i * 37 % 251);
    for (int p = 0; p < size * size; ++p) rgba[static_cast<std::size_t>(p) * 4 + 3] = 255;
    std::uint8_t* webp = nullptr;
    const std::size_t length = WebPEncodeLosslessRGBA(rgba.data(), size, size, size * 4, &webp);
    ASSERT_GT(length, 0u);
    TempDir dir;
    dir.write("texture.webp", std::string(webp, webp + length));
    WebPFree(webp);
    const Geometry g = makeBox({1, 1, 1});
    std::string text = writeSource(g);
    // The WebP image is the texture's source; the PNG-less fallback slot
    // is absent, as gltfpack writes with -tw.
    text.insert(text.rfind('}'),
                R"(, "extensionsUsed": ["EXT_texture_webp"], "extensionsRequired": ["EXT_texture_webp"],
        "images": [{"uri": "texture.webp"}],
        "textures": [{"extensions": {"EXT_texture_webp": {"source": 0}}}],
        "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}])");
    text.replace(text.find(R"("indices")"), 0, R"("material": 0, )");
    const ParsedModel m = parseModel(dir.write("webp.gltf", text));
    ASSERT_EQ(m.images.size(), 1u);
    EXPECT_EQ(m.images[0].width, size);
    EXPECT_EQ(m.images[0].rgba, rgba);
    EXPECT_EQ(m.materials[0].baseColorTexture.image, 0);
    EXPECT_TRUE(m.notDrawn.empty());
}

TEST(GltfCompressed, aBasisuTextureIsRefusedWhenRequiredAndDrawnFromItsFallbackWhenNot) {
    const Geometry g = makeBox({1, 1, 1});
    TempDir dir;
    std::string base = writeSource(g);
    base.replace(base.find(R"("indices")"), 0, R"("material": 0, )");
    const auto withTextures = [&](const std::string& name, const std::string& extensions) {
        std::string text = base;
        text.insert(text.rfind('}'), extensions + R"(,
            "images": [{"uri": "missing.ktx2"}, {"uri": "data:image/png;base64,)" +
                                         std::string(arcomp::test::kTinyPng) +
                                         R"("}],
            "textures": [{"source": 1, "extensions": {"KHR_texture_basisu": {"source": 0}}}],
            "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}])");
        return dir.write(name, text);
    };
    expectRefused(withTextures("required.gltf", R"(, "extensionsUsed": ["KHR_texture_basisu"],
                                                "extensionsRequired": ["KHR_texture_basisu"])"),
                  "/extensionsRequired/0", "KHR_texture_basisu, which arcomp cannot draw");
    const ParsedModel m = parseModel(withTextures("optional.gltf", R"(, "extensionsUsed": ["KHR_texture_basisu"])"));
    EXPECT_EQ(m.notDrawn, std::vector<std::string>{"KHR_texture_basisu"});
    EXPECT_EQ(m.materials[0].baseColorTexture.image, 1);
    EXPECT_EQ(m.images[1].width, 2);
    bool said = false;
    for (const std::string& w : m.warnings)
        said |= w.find("KHR_texture_basisu") != std::string::npos && w.find("fallback images") != std::string::npos;
    EXPECT_TRUE(said);
}

TEST(GltfCompressed, aDracoStreamThatDoesNotDecodeOrDoesNotMatchItsAccessorsIsRefusedByName) {
    const Geometry source = sourceSphere();
    TempDir dir;
    std::string text = writeDraco(source, true, 14, 10, 12);
    // The stream cut short.
    std::string cut = text;
    const auto length = cut.find("\"byteLength\"", cut.find("\"bufferViews\""));
    cut.replace(length, cut.find_first_of(",}", length) - length, "\"byteLength\": 16");
    expectRefused(dir.write("cut.gltf", cut), "/meshes/0/primitives/0/extensions/KHR_draco_mesh_compression",
                  "the Draco stream does not decode");
    // An accessor that declares one point more than the stream holds.
    std::string count = text;
    for (std::size_t at = count.find("\"count\""), k = 0; k < 3; at = count.find("\"count\"", at + 1), ++k) {
        const auto end = count.find_first_of(",}", at);
        const int declared = std::stoi(count.substr(at + 8, end - at - 8));
        count.replace(at, end - at, "\"count\": " + std::to_string(declared + 1));
    }
    try {
        parseModel(dir.write("count.gltf", count));
        ADD_FAILURE() << "an accessor that declares more points than the stream holds loaded";
    } catch (const ModelError& e) {
        // Whichever attribute is checked first: each accessor declares one point more.
        EXPECT_TRUE(e.where.starts_with("/accessors/") && e.where.ends_with("/count")) << e.what();
        EXPECT_NE(e.reason.find("but the Draco stream of"), std::string::npos) << e.what();
        EXPECT_NE(e.reason.find("KHR_draco_mesh_compression"), std::string::npos) << e.what();
    }
}

TEST(GltfCompressed, aMeshoptStreamThatDoesNotDecodeIsRefusedByName) {
    if (!hasGltfpack()) GTEST_SKIP() << "gltfpack is not installed (scripts/setup installs it)";
    TempDir dir;
    const fs::path src = dir.write("sphere.gltf", writeSource(sourceSphere()));
    const fs::path out = dir.path() / "packed.gltf";
    const auto r = arcomp::test::shell("gltfpack -i " + src.string() + " -o " + out.string() + " -c -noq");
    ASSERT_EQ(r.code, 0) << r.out;
    std::ifstream in(out);
    std::string text{std::istreambuf_iterator<char>(in), {}};
    ASSERT_NE(text.find("\"mode\":\"ATTRIBUTES\""), std::string::npos) << text;
    const std::string attributes = "\"mode\":\"ATTRIBUTES\"";
    text.replace(text.find(attributes), attributes.size(), "\"mode\":\"TRIANGLES\"");
    const auto rewritten = dir.write("packed.gltf", text);
    try {
        parseModel(rewritten);
        ADD_FAILURE() << "a stream decoded in the wrong mode loaded";
    } catch (const ModelError& e) {
        EXPECT_NE(e.where.find("/extensions/EXT_meshopt_compression"), std::string::npos) << e.what();
    }
}
