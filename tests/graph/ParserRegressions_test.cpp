// Inputs that once broke a scene-graph parser (found by the fuzzers in
// tools/fuzz, kept under tests/fuzz-regressions/<target>/), fed to it
// again: each must load or be refused with the parser's own error, under
// the sanitizers as well (scripts/test runs this suite).

#include "graph/io/LodFile.hpp"
#include "graph/io/ModelLoader.hpp"
#include "graph/io/SilhouetteFile.hpp"
#include "graph/io/VoxelFile.hpp"
#include "tests/support/ParserRegressions.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <iterator>
#include <typeinfo>
#include <vector>

using namespace arcomp;
using arcomp::test::eachLoadsOrIsRefused;
namespace fs = std::filesystem;

namespace {

std::vector<unsigned char> bytesOf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace

TEST(ParserRegressions, gltfInputsLoadOrAreRefusedWithModelError) {
    eachLoadsOrIsRefused<ModelError>("gltf", [](const fs::path& f) { parseGltf(f); });
}

// 485 bytes naming a VEC3 accessor of 55 million elements and no buffer
// view: refused by the components it would allocate, not let through to
// allocate 1.3 GB of zeros.
TEST(ParserRegressions, aBufferlessAccessorIsBoundedByWhatItWouldAllocate) {
    const fs::path file =
        fs::path(ARCOMP_SOURCE_DIR) / "tests/fuzz-regressions/gltf/a92d7ad28d42e72a807463424ddeae0cd6baf7e2";
    try {
        parseGltf(file);
        ADD_FAILURE() << "loaded, expected a refusal";
    } catch (const ModelError& e) {
        EXPECT_EQ(e.where, "/accessors/0/count") << e.what();
        EXPECT_NE(e.reason.find("count 55125123 is larger than supported without a buffer view (at most 5592405 VEC3"),
                  std::string::npos)
            << e.what();
    }
}

TEST(ParserRegressions, objInputsLoadOrAreRefusedWithModelError) {
    eachLoadsOrIsRefused<ModelError>("obj", [](const fs::path& f) { parseObj(f); });
}

TEST(ParserRegressions, lodInputsLoadOrAreRefusedWithModelError) {
    eachLoadsOrIsRefused<ModelError>("lod", [](const fs::path& f) { parseLodFile(bytesOf(f), f.string()); });
}

TEST(ParserRegressions, silhouetteInputsLoadOrAreRefusedWithModelError) {
    eachLoadsOrIsRefused<ModelError>("silhouette", [](const fs::path& f) {
        const auto b = bytesOf(f);
        decodeSilhouetteMesh(std::span(reinterpret_cast<const std::byte*>(b.data()), b.size()), f.string());
    });
}

TEST(ParserRegressions, voxelInputsLoadOrAreRefusedWithModelError) {
    eachLoadsOrIsRefused<ModelError>("voxel", [](const fs::path& f) { decodeVoxels(bytesOf(f), f.string()); });
}
