// arcomp-bench load --model F: how long loading a model takes through our
// validating loader, against tinyobjloader's bare parse of the same file
// (the baseline: what validation, vertex sharing and normals cost).

#include "graph/io/ModelLoader.hpp"
#include "tools/bench/report/BenchJson.hpp"
#include "tools/bench/report/Stats.hpp"
#include "tools/cli/Command.hpp"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <vector>

namespace arcomp {
namespace {

int loadBench(const std::string& model, int repeats) {
    using Clock = std::chrono::steady_clock;
    std::vector<double> ours, baseline;
    std::size_t triangles = 0, vertices = 0;
    for (int r = 0; r < repeats; ++r) {
        const auto t0 = Clock::now();
        Scene scene;
        loadModel(model, scene, scene.root());
        ours.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
        triangles = vertices = 0;
        for (const Geometry& g : scene.geometries()) {
            triangles += g.triangleCount();
            vertices += g.positions.size();
        }
    }
    const bool isObj = model.size() > 4 && model.substr(model.size() - 4) == ".obj";
    if (isObj) {
        for (int r = 0; r < repeats; ++r) {
            const auto t0 = Clock::now();
            tinyobj::ObjReader reader;
            reader.ParseFromFile(model);
            baseline.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
        }
    }
    BenchJson j;
    j.field("bench", "load").field("model", model).field("repeats", repeats);
    j.field("load_ms", Fixed{median(ours), 3})
        .field("load_ms_min", Fixed{*std::min_element(ours.begin(), ours.end()), 3});
    j.field("triangles", triangles).field("vertices", vertices);
    if (isObj)
        j.field("baseline", "tinyobjloader parse only")
            .field("baseline_ms", Fixed{median(baseline), 3})
            .field("overhead_ratio", Fixed{median(ours) / median(baseline), 3});
    std::printf("%s\n", j.str().c_str());
    return kExitOk;
}

const bool registered =
    registerCommand({"load", "Time loading a model", [](CommandLine& line) {
                         auto model = std::make_shared<std::string>();
                         auto repeats = std::make_shared<int>(5);
                         line.option("--model", *model, "Model file").required();
                         line.option("--repeats", *repeats, "Loads to time").range(1, 1000).showDefault();
                         return [model, repeats] { return loadBench(*model, *repeats); };
                     }});

}  // namespace
}  // namespace arcomp
