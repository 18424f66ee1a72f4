#include "graph/io/VoxelFile.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <random>

using namespace arcomp;

namespace {

VoxelGrid sample() {
    VoxelGrid g;
    g.resolution = 4;
    g.origin = {-1.0f, 0.5f, 2.0f};
    g.voxelSize = 0.25f;
    g.cells = {{0, 0, 0}, {3, 0, 0}, {1, 2, 0}, {0, 0, 3}};
    g.colors = {{255, 0, 0, 128}, {0, 255, 0, 255}, {0, 0, 255, 10}, {1, 2, 3, 4}};
    return g;
}

void expectVoxelsRejected(const std::vector<std::uint8_t>& bytes, const std::string& what) {
    try {
        decodeVoxels(bytes, "x.arvox");
        ADD_FAILURE() << "accepted a file with " << what;
    } catch (const ModelError& e) {
        EXPECT_EQ(e.file, "x.arvox");
        EXPECT_FALSE(e.where.empty()) << what;
    }
}

void putU64(std::vector<std::uint8_t>& b, std::size_t at, std::uint64_t v) {
    for (int i = 0; i < 8; ++i) b[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(v >> (8 * i));
}

}  // namespace

TEST(VoxelFile, roundTripsEveryField) {
    const VoxelGrid g = sample();
    const std::vector<std::uint8_t> bytes = encodeVoxels(g);
    EXPECT_EQ(bytes.size(), 40u + 4u * 10u);
    const VoxelGrid r = decodeVoxels(bytes);
    EXPECT_EQ(r.resolution, 4);
    EXPECT_EQ(r.origin, g.origin);
    EXPECT_EQ(r.voxelSize, g.voxelSize);
    EXPECT_EQ(r.cells, g.cells);
    EXPECT_EQ(r.colors, g.colors);
}

TEST(VoxelFile, writesAndReadsAFile) {
    const std::filesystem::path dir = std::filesystem::path(ARCOMP_TEST_OUTPUT);
    std::filesystem::create_directories(dir);
    const auto file = dir / "sample.arvox";
    writeVoxelFile(file, sample());
    EXPECT_EQ(readVoxelFile(file).cells, sample().cells);
    for (const auto& e : std::filesystem::directory_iterator(dir))  // no temporary left beside it
        EXPECT_NE(e.path().filename().string().rfind("sample.arvox.", 0), 0u) << e.path();
    EXPECT_THROW(readVoxelFile(dir / "missing.arvox"), ModelError);
}

TEST(VoxelFile, rejectsEveryBrokenField) {
    const std::vector<std::uint8_t> good = encodeVoxels(sample());
    expectVoxelsRejected({}, "no bytes");
    expectVoxelsRejected(std::vector<std::uint8_t>(good.begin(), good.begin() + 39), "a short header");
    auto b = good;
    b[0] = 'X';
    expectVoxelsRejected(b, "a wrong magic");
    b = good;
    b[8] = 2;
    expectVoxelsRejected(b, "version 2");
    b = good;
    std::memset(&b[12], 0, 4);
    expectVoxelsRejected(b, "resolution 0");
    b = good;
    b[12] = 0x01;
    b[13] = 0x10;
    expectVoxelsRejected(b, "resolution 4097");
    b = good;
    std::memset(&b[28], 0xff, 4);
    expectVoxelsRejected(b, "a NaN voxel size");
    b = good;
    std::memset(&b[28], 0, 4);
    expectVoxelsRejected(b, "a zero voxel size");
    b = good;
    b[19] = 0x7f;
    b[18] = 0x80;
    b[17] = 0;
    b[16] = 0;
    expectVoxelsRejected(b, "an infinite origin");
    b = good;
    putU64(b, 32, ~std::uint64_t{0});
    expectVoxelsRejected(b, "a count of 2^64 - 1");
    b = good;
    putU64(b, 32, 5);
    expectVoxelsRejected(b, "a count beyond the records");
    b = good;
    putU64(b, 32, 3);
    expectVoxelsRejected(b, "trailing bytes");
    b = good;
    b.pop_back();
    expectVoxelsRejected(b, "a cut record");
    b = good;
    b[40] = 4;
    expectVoxelsRejected(b, "a coordinate outside the grid");
    b = good;
    b[50] = 0;
    expectVoxelsRejected(b, "a voxel out of order");
    b = good;
    std::memcpy(&b[50], &b[40], 6);
    expectVoxelsRejected(b, "a repeated voxel");
}

TEST(VoxelFile, acceptsAnEmptyModel) {
    VoxelGrid g;
    g.resolution = 1;
    const VoxelGrid r = decodeVoxels(encodeVoxels(g));
    EXPECT_EQ(r.size(), 0u);
}

TEST(VoxelFile, randomlyMutatedFilesDecodeValidOrThrowModelError) {
    const std::vector<std::uint8_t> good = encodeVoxels(sample());
    std::mt19937 rng(11);
    int accepted = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        std::vector<std::uint8_t> b = good;
        const int edits = 1 + static_cast<int>(rng() % 4);
        for (int e = 0; e < edits; ++e) b[rng() % b.size()] = static_cast<std::uint8_t>(rng());
        if (rng() % 8 == 0) b.resize(rng() % (b.size() + 1));
        try {
            const VoxelGrid g = decodeVoxels(b);
            ++accepted;
            ASSERT_GE(g.resolution, 1);
            ASSERT_EQ(g.cells.size(), g.colors.size());
            for (std::size_t i = 0; i < g.size(); ++i) {
                for (int a = 0; a < 3; ++a) ASSERT_LT(g.cells[i][a], g.resolution);
                if (i > 0) {
                    ASSERT_LT(g.linearIndex(i - 1), g.linearIndex(i));
                }
            }
        } catch (const ModelError&) {}
    }
    EXPECT_GT(accepted, 0) << "colour-only edits must still decode";
}
