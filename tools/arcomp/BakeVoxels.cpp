// `arcomp bake voxels <model> --res 200 --out tree.arvox`: voxelizes a glTF
// or OBJ model into the voxel file that point-cloud nodes load (see
// graph/io/VoxelFile.hpp). Progress goes to stderr.

#include "graph/io/ModelLoader.hpp"
#include "graph/io/VoxelFile.hpp"
#include "graph/points/Voxelizer.hpp"
#include "tools/cli/Command.hpp"

#include <chrono>
#include <cstdio>
#include <memory>

namespace arcomp {

namespace {

struct BakeVoxelsOptions {
    std::string model;
    std::string out;
    int resolution = 200;
};

int bakeVoxels(const BakeVoxelsOptions& o) {
    if (o.resolution < 1 || o.resolution > kVoxelFileMaxResolution)
        throw InputError("--res " + std::to_string(o.resolution) + " outside [1, 4096]");
    const auto start = std::chrono::steady_clock::now();
    Scene scene;
    const LoadedModel loaded = loadModel(o.model, scene, scene.root());
    for (const std::string& w : loaded.warnings) std::fprintf(stderr, "warning: %s: %s\n", o.model.c_str(), w.c_str());
    scene.update();
    const std::vector<VoxelSource> sources = voxelSourcesOf(scene);
    if (sources.empty()) throw InputError(o.model + ": no triangles to voxelize");
    int lastPercent = -1;
    const VoxelGrid grid = voxelize(sources, o.resolution, [&](float done) {
        const int percent = static_cast<int>(done * 100.0f);
        if (percent / 5 != lastPercent / 5) std::fprintf(stderr, "\rvoxelizing %3d%%", percent);
        lastPercent = percent;
    });
    std::fprintf(stderr, "\n");
    writeVoxelFile(o.out, grid);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: %zu voxels in a %d^3 grid (voxel %.6g) -> %s in %.2f s\n", o.model.c_str(), grid.size(),
                grid.resolution, static_cast<double>(grid.voxelSize), o.out.c_str(), seconds);
    return kExitOk;
}

const bool registered =
    registerBake({"voxels", "Voxelize a model (glTF or OBJ) into an .arvox point model", [](CommandLine& line) {
                      auto o = std::make_shared<BakeVoxelsOptions>();
                      line.option("model", o->model, "glTF or OBJ file").required();
                      line.option("--res", o->resolution, "cells along the longest side").showDefault();
                      line.option("--out", o->out, "voxel file to write").required();
                      return [o] { return bakeVoxels(*o); };
                  }});

}  // namespace

}  // namespace arcomp
