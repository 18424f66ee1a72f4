// arcomp bake silhouette <model> --regions <spec> --out <file>: reduces a
// model for each viewpoint region and writes the shared-buffer result
// (graph/io/SilhouetteFile.hpp). Regions are given as
//   around:N                      N default boxes around the model (as the benchmark uses)
//   x0,y0,z0,x1,y1,z1[;...]       axis-aligned boxes in model space
//   a YAML file                   regions: [{box: [x0,y0,z0,x1,y1,z1]}, {vertices: [[x,y,z], ...]}]
// Progress goes to stderr, then one report line per region.

#include "graph/io/SilhouetteFile.hpp"
#include "graph/silhouette/FlatMesh.hpp"
#include "tools/cli/Command.hpp"

#include <yaml-cpp/yaml.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

namespace arcomp {

namespace {

struct Options {
    std::string model;
    std::string regions = "around:8";
    std::string out;
};

ViewRegion boxFrom(const std::vector<float>& v, const std::string& where) {
    if (v.size() != 6) throw InputError(where + ": a box needs 6 numbers x0,y0,z0,x1,y1,z1");
    try {
        return ViewRegion::fromBox({{v[0], v[1], v[2]}, {v[3], v[4], v[5]}});
    } catch (const std::invalid_argument& e) {
        throw InputError(where + ": " + e.what());
    }
}

std::vector<ViewRegion> regionsFromYaml(const std::string& file) {
    std::vector<ViewRegion> out;
    try {
        const YAML::Node root = YAML::LoadFile(file);
        const YAML::Node list = root["regions"];
        if (!list || !list.IsSequence()) throw InputError(file + ": expected a 'regions' list");
        for (std::size_t i = 0; i < list.size(); ++i) {
            const std::string where = file + ": regions[" + std::to_string(i) + "]";
            if (list[i]["box"]) {
                out.push_back(boxFrom(list[i]["box"].as<std::vector<float>>(), where));
            } else if (list[i]["vertices"]) {
                std::vector<glm::vec3> points;
                for (const auto& p : list[i]["vertices"]) {
                    const auto xyz = p.as<std::vector<float>>();
                    if (xyz.size() != 3) throw InputError(where + ": a vertex needs 3 numbers");
                    points.push_back({xyz[0], xyz[1], xyz[2]});
                }
                try {
                    out.push_back(ViewRegion::fromVertices(points));
                } catch (const std::invalid_argument& e) {
                    throw InputError(where + ": " + e.what());
                }
            } else {
                throw InputError(where + ": expected 'box' or 'vertices'");
            }
        }
    } catch (const YAML::Exception& e) {
        throw InputError(file + ": " + e.what());
    }
    return out;
}

std::vector<ViewRegion> parseRegions(const std::string& spec, const Sphere& bound) {
    if (spec.starts_with("around:")) {
        int n = 0;
        try {
            n = std::stoi(spec.substr(7));
        } catch (const std::exception&) {}
        if (n < 1 || n > 1024) throw InputError("--regions around:N needs N in 1..1024, got '" + spec + "'");
        return regionsAround(bound, n);
    }
    std::error_code ec;
    if (std::filesystem::is_regular_file(spec, ec)) return regionsFromYaml(spec);
    std::vector<ViewRegion> out;
    std::istringstream boxes(spec);
    std::string box;
    while (std::getline(boxes, box, ';')) {
        std::vector<float> v;
        std::istringstream numbers(box);
        std::string number;
        while (std::getline(numbers, number, ',')) {
            try {
                v.push_back(std::stof(number));
            } catch (const std::exception&) {
                throw InputError("--regions: '" + number + "' is not a number in box " + std::to_string(out.size()));
            }
        }
        out.push_back(boxFrom(v, "--regions box " + std::to_string(out.size())));
    }
    if (out.empty()) throw InputError("--regions: no regions given");
    return out;
}

int bake(const Options& o) {
    const FlatMesh model = flattenModel(parseObj(o.model));
    if (model.indices.empty()) throw InputError(o.model + ": no triangles");
    std::vector<ViewRegion> regions = parseRegions(o.regions, sphereAround(model.positions));
    std::vector<SilhouetteRegionReport> report;
    const auto t0 = std::chrono::steady_clock::now();
    const SilhouetteMesh mesh = bakeSilhouetteMesh(
        model.positions, model.indices, std::move(regions), &report, [](std::size_t done, std::size_t total) {
            const int width = 30, filled = static_cast<int>(width * done / total);
            std::cerr << "\rbaking [" << std::string(filled, '#') << std::string(width - filled, '.') << "] " << done
                      << "/" << total << (done == total ? "\n" : "") << std::flush;
        });
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    for (std::size_t r = 0; r < report.size(); ++r) {
        const SilhouetteRegionReport& p = report[r];
        std::cerr << "region " << r << ": FM " << p.front << "  BM " << p.back << " (kept for holes " << p.backKept
                  << ")  SM " << p.silhouette << "  triangles " << p.trianglesBefore << " -> " << p.trianglesAfter
                  << "  (FM " << p.front << " -> " << p.frontAfter << ", locked " << p.frontLocked
                  << ", rejected tries " << p.rejectedTries << ")\n";
    }
    writeSilhouetteFile(o.out, mesh);
    std::cerr << "wrote " << o.out << ": " << mesh.positions.size() << " vertices, " << mesh.indices.size()
              << " indices, " << mesh.regions.size() << " regions, bake " << ms << " ms\n";
    return kExitOk;
}

const bool registered =
    registerBake({"silhouette", "Silhouette-preserving reduction per viewpoint region", [](CommandLine& line) {
                      auto o = std::make_shared<Options>();
                      line.option("model", o->model, "OBJ model").required();
                      line.option("--regions", o->regions, "around:N, boxes x0,y0,z0,x1,y1,z1;... or a YAML file");
                      line.option("--out", o->out, "baked file to write").required();
                      return [o] { return bake(*o); };
                  }});

}  // namespace

}  // namespace arcomp
