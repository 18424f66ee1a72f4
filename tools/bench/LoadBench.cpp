// arcomp bench load --model F: how long loading a model takes through our
// validating loader, against tinyobjloader's bare parse of the same file
// (the baseline: what validation, vertex sharing and normals cost).

#include "graph/io/ModelLoader.hpp"
#include "tools/arcomp/Command.hpp"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <vector>

namespace arcomp {
namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

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
    std::printf("{\"bench\":\"load\",\"model\":\"%s\",\"repeats\":%d,\"load_ms\":%.3f,\"load_ms_min\":%.3f,"
                "\"triangles\":%zu,\"vertices\":%zu",
                model.c_str(), repeats, median(ours), *std::min_element(ours.begin(), ours.end()), triangles, vertices);
    if (isObj)
        std::printf(",\"baseline\":\"tinyobjloader parse only\",\"baseline_ms\":%.3f,\"overhead_ratio\":%.3f",
                    median(baseline), median(ours) / median(baseline));
    std::printf("}\n");
    return kExitOk;
}

const bool registered = registerBench({"load", "Time loading a model", [](CLI::App& app) {
                                           auto model = std::make_shared<std::string>();
                                           auto repeats = std::make_shared<int>(5);
                                           app.add_option("--model", *model, "Model file")->required();
                                           app.add_option("--repeats", *repeats, "Loads to time")
                                               ->check(CLI::Range(1, 1000))->capture_default_str();
                                           return [model, repeats] { return loadBench(*model, *repeats); };
                                       }});

} // namespace
} // namespace arcomp
