// Inputs that once broke a scene-graph parser (found by the fuzzers in
// tools/fuzz, kept under tests/fuzz-regressions/<target>/), fed to it
// again: each must load or be refused with the parser's own error, under
// the sanitizers as well (scripts/test runs this suite).

#include "graph/GazeSource.hpp"
#include "graph/LodFile.hpp"
#include "graph/ModelLoader.hpp"
#include "graph/SilhouetteFile.hpp"
#include "graph/VoxelFile.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <typeinfo>
#include <iterator>
#include <vector>

using namespace arcomp;
namespace fs = std::filesystem;

namespace {

std::vector<fs::path> regressionInputs(const std::string& target) {
    std::vector<fs::path> files;
    const fs::path dir = fs::path(ARCOMP_SOURCE_DIR) / "tests/fuzz-regressions" / target;
    if (fs::exists(dir))
        for (const auto& e : fs::directory_iterator(dir))
            if (e.is_regular_file()) files.push_back(e.path());
    return files;
}

std::vector<unsigned char> bytesOf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

// Runs `parse` on every input of `target`; only `Expected` may escape it.
template <class Expected>
void eachLoadsOrIsRefused(const std::string& target, const std::function<void(const fs::path&)>& parse) {
    const auto files = regressionInputs(target);
    ASSERT_FALSE(files.empty()) << "tests/fuzz-regressions/" << target << " holds no inputs";
    for (const fs::path& file : files) {
        try {
            parse(file);
        } catch (const Expected&) {
        } catch (const std::exception& e) {
            ADD_FAILURE() << file << ": escaped as " << typeid(e).name() << ": " << e.what();
        }
    }
}

} // namespace

TEST(ParserRegressions, gltfInputsLoadOrAreRefusedWithModelError) {
    eachLoadsOrIsRefused<ModelError>("gltf", [](const fs::path& f) { parseGltf(f); });
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

TEST(ParserRegressions, gazeTrackInputsLoadOrAreRefusedWithGazeTrackError) {
    eachLoadsOrIsRefused<GazeTrackError>("gaze", [](const fs::path& f) { readGazeTrackCsv(f); });
}
