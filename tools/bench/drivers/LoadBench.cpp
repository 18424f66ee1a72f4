// arcomp-bench load --model F: how long loading a model takes through our
// validating loader, against tinyobjloader's bare parse of the same file
// (the baseline: what validation, vertex sharing and normals cost).
//
// With --copies DIR: the model's geometry written as GLB four ways into
// DIR (plain floats and Draco, 14/10/12-bit, by arcomp's writer; meshopt by
// gltfpack -c -noq; meshopt and quantized by gltfpack -c), each loaded as
// often, with its file size and its load time beside the plain file's in
// the same run (the peer): decode_ms is a copy's load time less the plain
// file's, what decoding costs net of the smaller file to read.
//
//   arcomp-bench load --model ../shared/data/meshes/bunny.obj --copies build/load-copies

#include "graph/io/GltfWriter.hpp"
#include "graph/io/ModelLoader.hpp"
#include "tools/bench/probes/ShellCommand.hpp"
#include "tools/bench/report/BenchJson.hpp"
#include "tools/bench/report/Stats.hpp"
#include "tools/cli/Command.hpp"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <vector>

namespace arcomp {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// Median milliseconds of `repeats` parses of `file`.
double parseMs(const fs::path& file, int repeats) {
    std::vector<double> ms;
    for (int r = 0; r < repeats; ++r) {
        const auto t0 = Clock::now();
        const ParsedModel m = parseModel(file);
        ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    }
    return median(ms);
}

// The geometries of `model` as one GLB, plain or with each primitive
// Draco-compressed.
std::string glbOf(const ParsedModel& model, bool draco) {
    GltfWriter w;
    for (const Geometry& g : model.geometries) {
        std::string primitive;
        if (draco) {
            std::vector<DracoAttribute> attributes{
                {.semantic = "POSITION", .data = &g.positions[0].x, .components = 3, .quantizationBits = 14},
                {.semantic = "NORMAL", .data = &g.normals[0].x, .components = 3, .quantizationBits = 10}};
            if (!g.texcoords.empty())
                attributes.push_back(
                    {.semantic = "TEXCOORD_0", .data = &g.texcoords[0].x, .components = 2, .quantizationBits = 12});
            primitive = w.dracoPrimitive(g.positions.size(), attributes, g.indices);
        } else {
            std::string a = R"({"attributes": {"POSITION": )" +
                            std::to_string(w.accessor(&g.positions[0].x, g.positions.size(), "VEC3", GltfWriter::kFloat,
                                                      {.bounds = true})) +
                            R"(, "NORMAL": )" +
                            std::to_string(w.accessor(&g.normals[0].x, g.normals.size(), "VEC3", GltfWriter::kFloat));
            if (!g.texcoords.empty())
                a += R"(, "TEXCOORD_0": )" +
                     std::to_string(w.accessor(&g.texcoords[0].x, g.texcoords.size(), "VEC2", GltfWriter::kFloat));
            primitive =
                a + R"(}, "indices": )" +
                std::to_string(w.accessor(g.indices.data(), g.indices.size(), "SCALAR", GltfWriter::kUnsignedInt)) +
                "}";
        }
        const int mesh = GltfWriter::add(w.meshes, R"({"primitives": [)" + primitive + "]}");
        w.sceneNodes.push_back(GltfWriter::add(w.nodes, R"({"mesh": )" + std::to_string(mesh) + "}"));
    }
    return w.glb();
}

void writeText(const fs::path& file, const std::string& text) {
    std::ofstream out(file, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw std::runtime_error("cannot write " + file.string());
}

int copiesBench(const std::string& model, const fs::path& folder, int repeats) {
    const ParsedModel source = parseModel(model);
    fs::create_directories(folder);
    const fs::path plain = folder / "plain.glb", draco = folder / "draco.glb";
    writeText(plain, glbOf(source, false));
    writeText(draco, glbOf(source, true));
    struct Copy {
        const char* name;
        fs::path file;
        const char* packOptions;  // gltfpack's, or null for the copies arcomp writes
    };
    const std::vector<Copy> copies{{"plain", plain, nullptr},
                                   {"draco", draco, nullptr},
                                   {"meshopt", folder / "meshopt.glb", "-c -noq"},
                                   {"meshopt-quantized", folder / "meshopt-quantized.glb", "-c"}};
    for (const Copy& c : copies)
        if (c.packOptions) {
            const ShellResult packed = runShellCommand("gltfpack -i " + shellQuote(plain.string()) + " -o " +
                                                       shellQuote(c.file.string()) + " " + c.packOptions);
            if (packed.status != 0)
                throw std::runtime_error("gltfpack failed (scripts/setup installs it):\n" + packed.output);
        }
    BenchJson j;
    j.field("bench", "load").field("model", model).field("repeats", repeats);
    j.field("peer", "the plain GLB's load in the same run");
    double plainMs = 0.0;
    j.beginArray("copies");
    for (const Copy& c : copies) {
        const double ms = parseMs(c.file, repeats);
        if (std::string(c.name) == "plain") plainMs = ms;
        j.beginObject().field("copy", c.name).field("bytes", static_cast<std::uint64_t>(fs::file_size(c.file)));
        j.field("load_ms", Fixed{ms, 3}).field("decode_ms", Fixed{ms - plainMs, 3});
        j.field("load_ratio", Fixed{ms / plainMs, 3}).end();
    }
    j.end();
    std::printf("%s\n", j.str().c_str());
    return kExitOk;
}

int loadBench(const std::string& model, int repeats) {
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

const bool registered = registerCommand(
    {"load", "Time loading a model", [](CommandLine& line) {
         auto model = std::make_shared<std::string>();
         auto copies = std::make_shared<std::string>();
         auto repeats = std::make_shared<int>(5);
         line.option("--model", *model, "Model file").required();
         line.option("--copies", *copies, "Folder for the model's plain, Draco and meshopt glTF copies; times each");
         line.option("--repeats", *repeats, "Loads to time").range(1, 1000).showDefault();
         return [model, copies, repeats] {
             return copies->empty() ? loadBench(*model, *repeats) : copiesBench(*model, *copies, *repeats);
         };
     }});

}  // namespace
}  // namespace arcomp
