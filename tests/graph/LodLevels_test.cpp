#include "graph/io/LodFile.hpp"
#include "graph/io/ModelLoader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

using namespace arcomp;

namespace {

const float kRatios[3] = {1.0f, 0.25f, 0.05f};

std::vector<unsigned char> fileBytes(const std::vector<LodLevel>& levels) {
    const auto path = std::filesystem::temp_directory_path() / ("lod_test_" + std::to_string(::getpid()) + ".lod");
    writeLodFile(path, levels);
    std::ifstream in(path, std::ios::binary);
    std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::filesystem::remove(path);
    return bytes;
}

std::string errorOf(std::span<const unsigned char> bytes) {
    try {
        parseLodFile(bytes, "x.lod");
    } catch (const ModelError& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace

TEST(LodLevels, sphereLevelsReachRequestedCountsAndKeepAttributes) {
    const Geometry sphere = makeUvSphere(1.0f, 64, 32);
    const std::vector<LodLevel> levels = simplifyLevels(sphere, kRatios);
    ASSERT_EQ(levels.size(), 3u);
    EXPECT_EQ(levels[0].geometry.triangleCount(), sphere.triangleCount());
    for (int i = 1; i < 3; ++i) {
        const double want = sphere.triangleCount() * kRatios[i];
        EXPECT_NEAR(levels[i].geometry.triangleCount(), want, 0.1 * want) << "level " << i;
        EXPECT_GT(levels[i].error, 0.0f);
        const Geometry& g = levels[i].geometry;
        ASSERT_EQ(g.texcoords.size(), g.positions.size());
        for (std::size_t v = 0; v < g.positions.size(); ++v) {
            // Kept vertices are original ones: on the sphere, normal = position.
            EXPECT_NEAR(glm::length(g.positions[v]), 1.0f, 1e-5f);
            EXPECT_NEAR(glm::dot(g.normals[v], g.positions[v]), 1.0f, 1e-4f);
        }
    }
    EXPECT_LT(levels[1].error, levels[2].error);
}

TEST(LodLevels, bunnyLevelsWithinTenPercent) {
    const std::filesystem::path bunny = std::filesystem::path(ARCOMP_SHARED_DATA) / "meshes/bunny.obj";
    if (!std::filesystem::exists(bunny)) GTEST_SKIP() << "no shared data";
    const ParsedModel m = parseObj(bunny);
    ASSERT_EQ(m.geometries.size(), 1u);
    const std::vector<LodLevel> levels = simplifyLevels(m.geometries[0], kRatios);
    for (int i = 0; i < 3; ++i) {
        const double want = std::round(m.geometries[0].triangleCount() * kRatios[i]);
        EXPECT_NEAR(levels[i].geometry.triangleCount(), want, 0.1 * want) << "level " << i;
    }
}

TEST(LodLevels, generatedLodNodeHasOneMeshPerLevel) {
    Scene scene;
    LodTable lods;
    const MeshPart part{scene.addGeometry(makeUvSphere(2.0f, 32, 16)), scene.addMaterial({})};
    LodNode settings;
    settings.setThresholds({10.0f, 40.0f});
    const NodeId lod = addGeneratedLod(scene, lods, scene.root(), part, kRatios, settings);
    scene.update();
    const std::vector<NodeId> children = scene.children(lod);
    ASSERT_EQ(children.size(), 3u);
    EXPECT_EQ(scene.meshPart(children[0]).geometry, part.geometry);
    EXPECT_GT(scene.geometry(scene.meshPart(children[1]).geometry).triangleCount(),
              scene.geometry(scene.meshPart(children[2]).geometry).triangleCount());
    EXPECT_NEAR(lods.node(scene.payload(lod)).meanRadius, 2.0f, 1e-4f);
}

TEST(LodFile, roundTripKeepsLevels) {
    const std::vector<LodLevel> levels = simplifyLevels(makeUvSphere(1.0f, 16, 8), kRatios);
    const std::vector<LodLevel> back = parseLodFile(fileBytes(levels), "x.lod");
    ASSERT_EQ(back.size(), levels.size());
    for (std::size_t i = 0; i < levels.size(); ++i) {
        EXPECT_EQ(back[i].geometry.indices, levels[i].geometry.indices);
        EXPECT_EQ(back[i].geometry.positions, levels[i].geometry.positions);
        EXPECT_EQ(back[i].geometry.texcoords, levels[i].geometry.texcoords);
        EXPECT_FLOAT_EQ(back[i].ratio, levels[i].ratio);
        EXPECT_FLOAT_EQ(back[i].error, levels[i].error);
    }
}

TEST(LodFile, readerRejectsDamagedFilesWithPlace) {
    const std::vector<unsigned char> good = fileBytes(simplifyLevels(makeUvSphere(1.0f, 16, 8), kRatios));
    EXPECT_EQ(errorOf(std::span(good).first(5)), "x.lod: byte 0: file ends inside the header");
    std::vector<unsigned char> bad = good;
    bad[0] = 'X';
    EXPECT_EQ(errorOf(bad), "x.lod: byte 0: not an arcomp LOD file (expected \"ARCOMPLD\")");
    bad = good;
    bad[8] = 2;
    EXPECT_EQ(errorOf(bad), "x.lod: byte 12: version 2, expected 1");
    bad = good;
    bad[12] = 0;
    EXPECT_EQ(errorOf(bad), "x.lod: byte 16: level count 0, expected 1 to 8");
    EXPECT_NE(errorOf(std::span(good).first(good.size() - 1)).find("file ends inside indices"), std::string::npos)
        << errorOf(std::span(good).first(good.size() - 1));
    bad = good;
    bad.push_back(0);
    EXPECT_NE(errorOf(bad).find("1 bytes after the last level"), std::string::npos);
    // The last index of the last level, pointed past the vertices.
    bad = good;
    bad[bad.size() - 1] = 0x7f;
    EXPECT_NE(errorOf(bad).find("level 2: index"), std::string::npos) << errorOf(bad);
    // A vertex count far beyond the file is caught before anything is allocated.
    bad = good;
    bad[16 + 8 + 3] = 0xff;  // level 0's vertex count, high byte
    EXPECT_NE(errorOf(bad).find("file ends inside positions"), std::string::npos);
}

TEST(LodFile, missingFileIsModelError) { EXPECT_THROW(readLodFile("/nonexistent/x.lod"), ModelError); }

TEST(LodFile, mutatedBytesParseOrThrowModelError) {
    const std::vector<unsigned char> good = fileBytes(simplifyLevels(makeUvSphere(1.0f, 8, 6), kRatios));
    std::uint32_t state = 12345;
    const auto next = [&state] { return state = state * 1664525u + 1013904223u; };
    for (int round = 0; round < 2000; ++round) {
        std::vector<unsigned char> bytes = good;
        for (int k = 0; k < 1 + round % 4; ++k) bytes[next() % bytes.size()] = static_cast<unsigned char>(next() >> 24);
        if (round % 7 == 0) bytes.resize(next() % bytes.size());
        try {
            const std::vector<LodLevel> levels = parseLodFile(bytes, "x.lod");
            for (const LodLevel& l : levels)
                for (std::uint32_t i : l.geometry.indices) ASSERT_LT(i, l.geometry.positions.size());
        } catch (const ModelError&) {}
    }
}

TEST(LodFile, loadOrSimplifyReusesLevelsMadeFromTheSameMeshAndRatios) {
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / ("lod_cache_test_" + std::to_string(::getpid()) + ".lod");
    std::filesystem::remove(file);
    const Geometry sphere = makeUvSphere(1.0f, 16, 8);
    const LoadedOrSimplified first = loadOrSimplifyLevels(file, sphere, kRatios);
    EXPECT_FALSE(first.loaded);
    EXPECT_NE(first.note.find("not found"), std::string::npos) << first.note;
    const LoadedOrSimplified second = loadOrSimplifyLevels(file, sphere, kRatios);
    EXPECT_TRUE(second.loaded) << second.note;
    ASSERT_EQ(second.levels.size(), first.levels.size());
    for (std::size_t i = 0; i < first.levels.size(); ++i)
        EXPECT_EQ(second.levels[i].geometry.indices, first.levels[i].geometry.indices);

    const float otherRatios[2] = {1.0f, 0.5f};
    const LoadedOrSimplified third = loadOrSimplifyLevels(file, sphere, otherRatios);
    EXPECT_FALSE(third.loaded);
    EXPECT_NE(third.note.find("other ratios"), std::string::npos) << third.note;
    EXPECT_EQ(third.levels.size(), 2u);
    // The file now holds the other ratios' levels, made from the sphere, not this one.
    const LoadedOrSimplified otherMesh = loadOrSimplifyLevels(file, makeUvSphere(1.0f, 12, 6), otherRatios);
    EXPECT_FALSE(otherMesh.loaded);
    std::ofstream(file, std::ios::trunc) << "not a lod file";
    const LoadedOrSimplified damaged = loadOrSimplifyLevels(file, sphere, kRatios);
    EXPECT_FALSE(damaged.loaded);
    EXPECT_EQ(damaged.levels.size(), 3u);
    std::filesystem::remove(file);
}

namespace {

// A sphere that carries every attribute the levels and the file keep:
// TEXCOORD_1 is TEXCOORD_0 mirrored in u, and tangents generated from it.
Geometry sphereWithEveryAttribute(int slices, int stacks) {
    Geometry g = makeUvSphere(1.0f, slices, stacks);
    for (const glm::vec2& uv : g.texcoords) g.texcoords1.push_back({1.0f - uv.x, uv.y});
    g.tangents = computeTangents(g.positions, g.normals, g.texcoords, g.indices);
    g.tangentsGenerated = true;
    return g;
}

}  // namespace

TEST(LodLevels, simplifiedLevelsKeepEachVertexsTexcoord1AndTangent) {
    const Geometry sphere = sphereWithEveryAttribute(32, 16);
    const std::vector<LodLevel> levels = simplifyLevels(sphere, kRatios);
    for (int i = 1; i < 3; ++i) {
        const Geometry& g = levels[i].geometry;
        ASSERT_EQ(g.texcoords1.size(), g.positions.size()) << "level " << i;
        ASSERT_EQ(g.tangents.size(), g.positions.size()) << "level " << i;
        EXPECT_TRUE(g.tangentsGenerated);
        for (std::size_t v = 0; v < g.positions.size(); ++v) {
            // The sphere's (position, TEXCOORD_0) pairs are unique: they name
            // the vertex a kept one came from.
            std::size_t from = sphere.positions.size();
            for (std::size_t o = 0; o < sphere.positions.size() && from == sphere.positions.size(); ++o)
                if (sphere.positions[o] == g.positions[v] && sphere.texcoords[o] == g.texcoords[v]) from = o;
            ASSERT_LT(from, sphere.positions.size());
            EXPECT_EQ(g.texcoords1[v], sphere.texcoords1[from]);
            EXPECT_EQ(g.tangents[v], sphere.tangents[from]);
        }
    }
}

TEST(LodFile, roundTripKeepsTexcoord1AndTangents) {
    std::vector<LodLevel> levels = simplifyLevels(sphereWithEveryAttribute(16, 8), kRatios);
    levels[2].geometry.tangentsGenerated = false;  // as if the file had brought them
    const std::vector<LodLevel> back = parseLodFile(fileBytes(levels), "x.lod");
    ASSERT_EQ(back.size(), levels.size());
    for (std::size_t i = 0; i < levels.size(); ++i) {
        EXPECT_EQ(back[i].geometry.texcoords1, levels[i].geometry.texcoords1);
        EXPECT_EQ(back[i].geometry.tangents, levels[i].geometry.tangents);
        EXPECT_EQ(back[i].geometry.tangentsGenerated, levels[i].geometry.tangentsGenerated);
    }
}

TEST(LodFile, aCacheMadeBeforeTheMeshHadTangentsIsMadeAgain) {
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / ("lod_tangents_test_" + std::to_string(::getpid()) + ".lod");
    std::filesystem::remove(file);
    const Geometry plain = makeUvSphere(1.0f, 16, 8);
    EXPECT_FALSE(loadOrSimplifyLevels(file, plain, kRatios).loaded);
    const Geometry withTangents = sphereWithEveryAttribute(16, 8);
    const LoadedOrSimplified again = loadOrSimplifyLevels(file, withTangents, kRatios);
    EXPECT_FALSE(again.loaded) << again.note;
    EXPECT_EQ(again.levels[1].geometry.tangents.size(), again.levels[1].geometry.positions.size());
    const LoadedOrSimplified cached = loadOrSimplifyLevels(file, withTangents, kRatios);
    EXPECT_TRUE(cached.loaded) << cached.note;
    EXPECT_EQ(cached.levels[1].geometry.tangents, again.levels[1].geometry.tangents);
    std::filesystem::remove(file);
}

// A skinned mesh's levels are skinned too: each kept vertex keeps its
// joints and weights, each level's mesh node the part's skin, and the
// levels are simplified afresh rather than cached without them.
TEST(LodLevels, levelsOfASkinnedMeshKeepJointsWeightsAndTheSkin) {
    Geometry sphere = makeUvSphere(1.0f, 32, 16);
    // Weights from height, so that each position has its own: (upper, lower).
    for (const glm::vec3& p : sphere.positions) {
        const float up = (p.y + 1.0f) * 0.5f;
        sphere.joints.push_back({0, 1, 0, 0});
        sphere.weights.push_back({up, 1.0f - up, 0, 0});
    }
    Scene scene;
    const std::uint32_t sourceId = scene.addGeometry(sphere);
    const NodeId joints[2] = {scene.addTransform(scene.root(), glm::mat4(1.0f)),
                              scene.addTransform(scene.root(), glm::mat4(1.0f))};
    const glm::mat4 binds[2] = {glm::mat4(1.0f), glm::mat4(1.0f)};
    const std::uint32_t skin = scene.addSkin(scene.root(), joints, binds);
    const MeshPart part{sourceId, scene.addMaterial({}), skin};
    LodTable lods;
    LodNode settings;
    settings.setThresholds({10.0f, 40.0f});
    const NodeId lod = addGeneratedLod(scene, lods, scene.root(), part, kRatios, settings);
    const Geometry& source = scene.geometry(sourceId);  // after the levels were added to the scene's geometries
    for (const NodeId level : scene.children(lod)) {
        EXPECT_EQ(scene.meshPart(level).skin, skin);
        const Geometry& g = scene.geometry(scene.meshPart(level).geometry);
        ASSERT_TRUE(g.hasSkinInfluences());
        for (std::size_t v = 0; v < g.positions.size(); ++v) {
            const auto from =
                std::find(source.positions.begin(), source.positions.end(), g.positions[v]) - source.positions.begin();
            ASSERT_LT(static_cast<std::size_t>(from), source.positions.size());
            EXPECT_EQ(g.joints[v], source.joints[static_cast<std::size_t>(from)]);
            EXPECT_EQ(g.weights[v], source.weights[static_cast<std::size_t>(from)]);
        }
    }
    const auto file = std::filesystem::temp_directory_path() / ("lod_skin_test_" + std::to_string(::getpid()) + ".lod");
    const LoadedOrSimplified cached = loadOrSimplifyLevels(file, source, kRatios);
    EXPECT_FALSE(cached.loaded);
    EXPECT_FALSE(std::filesystem::exists(file)) << ".lod holds no joints: a skinned mesh's levels are not written";
    EXPECT_TRUE(cached.levels[1].geometry.hasSkinInfluences());
}
