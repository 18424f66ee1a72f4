#include "graph/io/SilhouetteFile.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

using namespace arcomp;

namespace {

SilhouetteMesh smallMesh() {
    const Geometry sphere = makeUvSphere(1.0f, 12, 6);
    const glm::vec3 tetra[] = {{3, 0, 0}, {4, 0, 0}, {3, 1, 0}, {3, 0, 1}};
    return bakeSilhouetteMesh(
        sphere.positions, sphere.indices,
        {ViewRegion::fromBox({{-0.5f, -0.5f, 3}, {0.5f, 0.5f, 4}}), ViewRegion::fromVertices(tetra)});
}

void putU32(std::vector<std::byte>& b, std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) b[at + i] = static_cast<std::byte>((v >> (8 * i)) & 0xff);
}

}  // namespace

TEST(SilhouetteFile, roundTripKeepsBufferRangesAndRegions) {
    const SilhouetteMesh m = smallMesh();
    const SilhouetteMesh back = decodeSilhouetteMesh(encodeSilhouetteMesh(m));
    EXPECT_EQ(back.positions, m.positions);
    EXPECT_EQ(back.indices, m.indices);
    EXPECT_EQ(back.full.indexCount, m.full.indexCount);
    ASSERT_EQ(back.ranges.size(), 2u);
    EXPECT_EQ(back.ranges[1].firstIndex, m.ranges[1].firstIndex);
    EXPECT_EQ(back.regionAt({0, 0, 3.5f}), 0);
    EXPECT_EQ(back.regionAt({3.2f, 0.2f, 0.2f}), 1);
}

TEST(SilhouetteFile, everyTruncationIsRefused) {
    const std::vector<std::byte> bytes = encodeSilhouetteMesh(smallMesh());
    for (std::size_t n = 0; n < bytes.size(); n += 7)
        EXPECT_THROW(decodeSilhouetteMesh(std::span(bytes).first(n)), ModelError) << n << " bytes";
}

TEST(SilhouetteFile, badHeaderIndicesAndRangesAreRefused) {
    const std::vector<std::byte> good = encodeSilhouetteMesh(smallMesh());
    auto refused = [](std::vector<std::byte> b) {
        try {
            decodeSilhouetteMesh(b, "test.sil");
        } catch (const ModelError& e) {
            return std::string(e.what()).find("test.sil: byte ") == 0;
        }
        return false;
    };
    auto b = good;
    b[0] = std::byte{'X'};
    EXPECT_TRUE(refused(b));  // magic
    b = good;
    putU32(b, 8, 2);
    EXPECT_TRUE(refused(b));  // version
    b = good;
    putU32(b, 12, 0xffffffffu);
    EXPECT_TRUE(refused(b));  // vertex count beyond the file, refused before allocating
    b = good;
    putU32(b, 36 + 12 * smallMesh().positions.size(), 1u << 30);
    EXPECT_TRUE(refused(b));  // first index out of range
    b = good;
    putU32(b, 32, 0xfffffff0u);
    EXPECT_TRUE(refused(b));  // full range past the index list
    b = good;
    b.push_back(std::byte{0});
    EXPECT_TRUE(refused(b));  // trailing bytes
    b = good;
    putU32(b, 36, 0x7fc00000u);
    EXPECT_TRUE(refused(b));  // NaN position
    EXPECT_FALSE(refused(good));
}

TEST(SilhouetteFile, corruptedBytesGiveAMeshOrModelErrorNothingElse) {
    const std::vector<std::byte> good = encodeSilhouetteMesh(smallMesh());
    std::mt19937 rng(3);
    std::uniform_int_distribution<std::size_t> where(0, good.size() - 1);
    std::uniform_int_distribution<int> value(0, 255);
    std::size_t accepted = 0;
    for (int round = 0; round < 2000; ++round) {
        std::vector<std::byte> b = good;
        for (int k = 0; k < 1 + round % 4; ++k) b[where(rng)] = static_cast<std::byte>(value(rng));
        try {
            const SilhouetteMesh m = decodeSilhouetteMesh(b);
            for (std::uint32_t i : m.indices) ASSERT_LT(i, m.positions.size());
            for (const SilhouetteRange& r : m.ranges)
                ASSERT_LE(std::uint64_t{r.firstIndex} + r.indexCount, m.indices.size());
            ++accepted;
        } catch (const ModelError&) {}
    }
    EXPECT_LT(accepted, 2000u);  // most corruptions land in positions or indices and some must be refused
}

TEST(SilhouetteFile, loadOrBakeReusesAMatchingFileAndRebakesOtherwise) {
    const std::filesystem::path folder = std::filesystem::path(ARCOMP_TEST_OUTPUT) / "silhouette_file";
    std::filesystem::create_directories(folder);
    const std::filesystem::path file = folder / "sphere.sil";
    std::filesystem::remove(file);
    const Geometry sphere = makeUvSphere(1.0f, 12, 6);
    std::vector<ViewRegion> regions = {ViewRegion::fromBox({{-0.5f, -0.5f, 3}, {0.5f, 0.5f, 4}})};
    const LoadedOrBaked first = loadOrBakeSilhouetteMesh(file, sphere.positions, sphere.indices, regions);
    EXPECT_FALSE(first.loaded);
    EXPECT_NE(first.note.find("not found"), std::string::npos) << first.note;
    const LoadedOrBaked second = loadOrBakeSilhouetteMesh(file, sphere.positions, sphere.indices, regions);
    EXPECT_TRUE(second.loaded) << second.note;
    EXPECT_EQ(second.mesh.indices, first.mesh.indices);
    regions.push_back(ViewRegion::fromBox({{-0.5f, -0.5f, -4}, {0.5f, 0.5f, -3}}));
    const LoadedOrBaked third = loadOrBakeSilhouetteMesh(file, sphere.positions, sphere.indices, regions);
    EXPECT_FALSE(third.loaded);
    EXPECT_NE(third.note.find("other regions"), std::string::npos) << third.note;
    EXPECT_EQ(third.mesh.regions.size(), 2u);
    std::ofstream(file, std::ios::trunc) << "not a silhouette file";
    const LoadedOrBaked fourth = loadOrBakeSilhouetteMesh(file, sphere.positions, sphere.indices, regions);
    EXPECT_FALSE(fourth.loaded);
    EXPECT_NE(fourth.note.find("bad magic"), std::string::npos) << fourth.note;
}
