#include "graph/io/Base64.hpp"
#include "graph/io/ModelLoader.hpp"

#include "../support/TempDir.hpp"

#include <gtest/gtest.h>

#include <cstring>

using namespace arcomp;
using arcomp::test::TempDir;

namespace {

// One triangle: 3 float positions (36 bytes) then 3 u16 indices (6 bytes).
std::vector<unsigned char> triangleBytes(std::uint16_t lastIndex = 2) {
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const std::uint16_t indices[3] = {0, 1, lastIndex};
    std::vector<unsigned char> b(42 + 2);
    std::memcpy(b.data(), positions, 36);
    std::memcpy(b.data() + 36, indices, 6);
    return b;
}

std::string triangleGltf(const std::string& bufferUri, const std::string& extra = "", int positionCount = 3,
                         const std::string& nodes = R"([{"mesh": 0}])") {
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": )" + nodes + R"(,
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
      "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": )" +
           std::to_string(positionCount) + R"(, "type": "VEC3"},
        {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
      "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
      "buffers": [{"byteLength": 44, "uri": ")" +
           bufferUri + "\"}]" + extra + "}";
}

std::string dataUri(const std::vector<unsigned char>& bytes) {
    return "data:application/octet-stream;base64," + arcomp::base64(bytes);
}

void expectModelRejected(const std::filesystem::path& file, const std::string& where, const std::string& reasonPart) {
    Scene scene;
    const std::size_t before = scene.nodeCount();
    try {
        loadModel(file, scene, scene.root());
        FAIL() << file << " loaded but should have been rejected";
    } catch (const ModelError& e) {
        EXPECT_EQ(e.where, where) << e.what();
        EXPECT_NE(e.reason.find(reasonPart), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(file.filename().string()), std::string::npos);
    }
    EXPECT_EQ(scene.nodeCount(), before) << "a rejected model must leave the scene untouched";
}

}  // namespace

TEST(GltfLoader, loadsATriangleFromAnEmbeddedBuffer) {
    TempDir dir;
    const auto file = dir.write("tri.gltf", triangleGltf(dataUri(triangleBytes())));
    Scene scene;
    const LoadedModel m = loadModel(file, scene, scene.root());
    ASSERT_EQ(scene.geometries().size(), 1u);
    const Geometry& g = scene.geometry(0);
    EXPECT_EQ(g.triangleCount(), 1u);
    ASSERT_EQ(g.normals.size(), 3u);  // computed: the file has none
    EXPECT_NEAR(g.normals[0].z, 1.0f, 1e-6f);
    EXPECT_EQ(scene.name(m.root), "tri");
}

TEST(GltfLoader, loadsAnExternalBufferInsideTheFolder) {
    TempDir dir;
    const auto bytes = triangleBytes();
    dir.write("data/tri.bin", std::string(bytes.begin(), bytes.end()));
    const auto file = dir.write("tri.gltf", triangleGltf("data/tri.bin"));
    Scene scene;
    loadModel(file, scene, scene.root());
    EXPECT_EQ(scene.geometry(0).triangleCount(), 1u);
}

TEST(GltfLoader, refusesUrisThatLeaveTheModelFolder) {
    TempDir dir;
    const auto bytes = triangleBytes();
    dir.write("outside.bin", std::string(bytes.begin(), bytes.end()));
    const auto up = dir.write("models/up.gltf", triangleGltf("../outside.bin"));
    expectModelRejected(up, "/buffers/0/uri", "outside the model's folder");
    const auto absolute = dir.write("models/abs.gltf", triangleGltf((dir.path() / "outside.bin").string()));
    expectModelRejected(absolute, "/buffers/0/uri", "absolute path");
    const auto scheme = dir.write("models/scheme.gltf", triangleGltf("file:///etc/passwd"));
    expectModelRejected(scheme, "/buffers/0/uri", "scheme");
}

TEST(GltfLoader, rejectsAnIndexOutOfRangeNamingTheAccessor) {
    TempDir dir;
    const auto file = dir.write("oob.gltf", triangleGltf(dataUri(triangleBytes(7))));
    expectModelRejected(file, "/accessors/1", "index 7 at element 2 is out of range for 3 vertices");
}

TEST(GltfLoader, rejectsAnAccessorLongerThanItsBufferView) {
    TempDir dir;
    const auto file = dir.write("long.gltf", triangleGltf(dataUri(triangleBytes()), "", 4));
    expectModelRejected(file, "/accessors/0", "do not fit in buffer view 0");
}

TEST(GltfLoader, rejectsACycleInTheNodeGraph) {
    TempDir dir;
    const auto file = dir.write(
        "cycle.gltf", triangleGltf(dataUri(triangleBytes()), "", 3,
                                   R"([{"mesh": 0, "children": [1]}, {"children": [2]}, {"children": [1]}])"));
    expectModelRejected(file, "/nodes/2/children/0", "already has parent");
}

TEST(GltfLoader, rejectsUnsupportedRequiredExtensionsByName) {
    TempDir dir;
    const auto file = dir.write(
        "basisu.gltf",
        triangleGltf(dataUri(triangleBytes()),
                     R"(, "extensionsUsed": ["KHR_texture_basisu"], "extensionsRequired": ["KHR_texture_basisu"])"));
    expectModelRejected(file, "/extensionsRequired/0",
                        "requires extension KHR_texture_basisu, which arcomp cannot draw: Debian 12 has no KTX2 "
                        "decoder; re-export with PNG, JPEG or WebP textures (gltfpack without -tc)");
    const auto notAList = dir.write(
        "string.gltf", triangleGltf(dataUri(triangleBytes()), R"(, "extensionsRequired": "KHR_texture_basisu")"));
    expectModelRejected(notAList, "/extensionsRequired", "is not an array of extension names");
}

// A Draco primitive's accessors have no bufferView, which tinygltf alone
// refuses without naming Draco; arcomp decodes the stream first, and a
// stream that does not decode is refused at the extension.
TEST(GltfLoader, aDracoStreamThatDoesNotDecodeIsRefusedAtItsExtension) {
    TempDir dir;
    const auto file = dir.write("draco-box.gltf", R"({"asset": {"version": "2.0"},
      "extensionsUsed": ["KHR_draco_mesh_compression"], "extensionsRequired": ["KHR_draco_mesh_compression"],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1,
        "extensions": {"KHR_draco_mesh_compression": {"bufferView": 0, "attributes": {"POSITION": 0}}}}]}],
      "accessors": [{"componentType": 5126, "count": 3, "type": "VEC3", "max": [1, 1, 0], "min": [0, 0, 0]},
                    {"componentType": 5123, "count": 3, "type": "SCALAR"}],
      "bufferViews": [{"buffer": 0, "byteLength": 4}],
      "buffers": [{"byteLength": 4, "uri": "data:application/octet-stream;base64,AAAAAA=="}],
      "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]})");
    expectModelRejected(file, "/meshes/0/primitives/0/extensions/KHR_draco_mesh_compression",
                        "the Draco stream does not decode");
}

TEST(GltfLoader, aGlbWithAMeshoptViewThatDoesNotDecodeIsRefusedAtItsExtension) {
    TempDir dir;
    std::string json =
        R"({"asset": {"version": "2.0"}, "extensionsUsed": ["EXT_meshopt_compression"],
            "extensionsRequired": ["EXT_meshopt_compression"],
            "buffers": [{"byteLength": 8}, {"byteLength": 48, "extensions": {"EXT_meshopt_compression": {"fallback": true}}}],
            "bufferViews": [{"buffer": 1, "byteLength": 48, "byteStride": 12,
              "extensions": {"EXT_meshopt_compression": {"buffer": 0, "byteLength": 8, "byteStride": 12,
                                                         "count": 4, "mode": "ATTRIBUTES"}}}]})";
    while (json.size() % 4) json += ' ';
    std::string glb = "glTF";
    const auto u32 = [&glb](std::uint32_t v) {
        for (int k = 0; k < 4; ++k) glb += static_cast<char>((v >> (8 * k)) & 0xFF);
    };
    u32(2);
    u32(static_cast<std::uint32_t>(20 + json.size() + 8 + 8));
    u32(static_cast<std::uint32_t>(json.size()));
    glb += "JSON" + json;
    u32(8);
    glb += std::string("BIN\0", 4) + std::string(8, '\x7f');
    expectModelRejected(dir.write("meshopt.glb", glb), "/bufferViews/0/extensions/EXT_meshopt_compression",
                        "the ATTRIBUTES stream does not decode");
}

TEST(GltfLoader, eachUsedExtensionItDoesNotDrawIsOneWarningAndTheModelLoads) {
    TempDir dir;
    const auto file = dir.write(
        "lights.gltf",
        triangleGltf(
            dataUri(triangleBytes()),
            R"(, "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_unlit", "KHR_materials_variants"])"));
    Scene scene;
    const LoadedModel m = loadModel(file, scene, scene.root());
    std::vector<std::string> about;
    for (const std::string& w : m.warnings)
        if (w.find("which arcomp does not draw") != std::string::npos) about.push_back(w);
    ASSERT_EQ(about.size(), 2u);
    EXPECT_NE(about[0].find("KHR_lights_punctual"), std::string::npos) << about[0];
    EXPECT_NE(about[1].find("KHR_materials_variants"), std::string::npos) << about[1];
    EXPECT_EQ(m.notDrawn, (std::vector<std::string>{"KHR_lights_punctual", "KHR_materials_variants"}));
}

// An image that does not decode costs its texture, with a warning that
// names the real cause; a buffer's data URI that does not decode is refused.
TEST(GltfLoader, aDataUriThatDoesNotDecodeSaysItsRealCause) {
    TempDir dir;
    const auto warningFor = [&](const std::string& name, const std::string& uri) {
        Scene scene;
        const LoadedModel m = loadModel(
            dir.write(name, triangleGltf(dataUri(triangleBytes()), R"(, "images": [{"uri": ")" + uri + "\"}]")), scene,
            scene.root());
        return m.warnings.empty() ? std::string() : m.warnings.back();
    };
    EXPECT_NE(warningFor("webp.gltf", "data:image/webp;base64,UklGRhoAAABXRUJQ").find("WebP image (EXT_texture_webp)"),
              std::string::npos);
    EXPECT_NE(
        warningFor("ktx2.gltf", "data:image/ktx2;base64,q0tUWCAyMLsNChoK").find("KTX2 image (KHR_texture_basisu)"),
        std::string::npos);
    EXPECT_NE(warningFor("plain.gltf", "data:image/png,not-a-png").find("does not decode as PNG, JPEG or WebP"),
              std::string::npos);
    expectModelRejected(dir.write("buffer.gltf", triangleGltf("data:application/octet-stream;base64,A*A=")),
                        "/buffers/0/uri", "says base64 but holds characters");
    // RFC 2397 without base64: percent-encoded bytes, as the validator's
    // corpus writes one.
    expectModelRejected(dir.write("short.gltf", triangleGltf("data:application/gltf-buffer,%00%01")),
                        "/buffers/0/byteLength", "but its uri holds 2");
}

TEST(GltfLoader, rejectsGarbageAndEmptyFiles) {
    TempDir dir;
    Scene scene;
    EXPECT_THROW(loadModel(dir.write("empty.gltf", ""), scene, scene.root()), ModelError);
    EXPECT_THROW(loadModel(dir.write("junk.glb", "glTF\x02\0\0\0\xff\xff\xff\xff"), scene, scene.root()), ModelError);
    EXPECT_THROW(loadModel(dir.write("text.gltf", "{\"asset\": "), scene, scene.root()), ModelError);
    EXPECT_THROW(loadModel(dir.path() / "missing.gltf", scene, scene.root()), ModelError);
    EXPECT_EQ(scene.nodeCount(), 1u);
}

TEST(ObjLoader, loadsTheStanfordBunny) {
    const auto bunny = arcomp::test::sharedData() / "meshes/bunny.obj";
    if (!std::filesystem::exists(bunny)) GTEST_SKIP() << "shared test data is absent";
    Scene scene;
    loadModel(bunny, scene, scene.root());
    ASSERT_EQ(scene.geometries().size(), 1u);
    EXPECT_EQ(scene.geometry(0).triangleCount(), 27864u);
    EXPECT_EQ(scene.geometry(0).positions.size(), 13934u);
    EXPECT_GT(scene.geometry(0).bound.radius, 0.05f);
}

TEST(ObjLoader, computesMissingNormalsAndRejectsBadFaces) {
    TempDir dir;
    Scene scene;
    loadModel(dir.write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"), scene, scene.root());
    ASSERT_EQ(scene.geometry(0).triangleCount(), 2u);
    EXPECT_NEAR(scene.geometry(0).normals[0].z, 1.0f, 1e-6f);
    EXPECT_THROW(loadModel(dir.write("bad.obj", "v 0 0 0\nf 1 2 3\n"), scene, scene.root()), ModelError);
    EXPECT_THROW(loadModel(dir.write("none.obj", "# nothing\n"), scene, scene.root()), ModelError);
    EXPECT_THROW(loadModel(dir.write("bin.obj", std::string("v 0\0\0 0", 8)), scene, scene.root()), ModelError);
}

TEST(ObjLoader, ignoresAMaterialLibraryOutsideTheFolderWithAWarning) {
    TempDir dir;
    dir.write("secret.mtl", "newmtl red\nKd 1 0 0\n");
    Scene scene;
    const LoadedModel m =
        loadModel(dir.write("sub/tri.obj", "mtllib ../secret.mtl\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
                  scene, scene.root());
    ASSERT_FALSE(m.warnings.empty());
    EXPECT_NE(m.warnings[0].find("outside the model's folder"), std::string::npos);
    EXPECT_EQ(scene.geometry(0).triangleCount(), 1u);
}
