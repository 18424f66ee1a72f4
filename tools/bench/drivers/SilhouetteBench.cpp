// arcomp-bench silhouette: the proof by rendering that a region's reduced
// mesh has the full mesh's silhouette from anywhere in the region, against
// plain simplification to the same triangle count (DESIGN.md section 4).
// Masks come from the CPU coverage rasterizer, so the figures are
// deterministic and need no GL.

#include "graph/core/View.hpp"
#include "graph/silhouette/CoverageRaster.hpp"
#include "graph/silhouette/FlatMesh.hpp"
#include "graph/silhouette/SilhouetteMesh.hpp"
#include "tools/bench/report/BenchJson.hpp"
#include "tools/cli/Command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <random>

namespace arcomp {

namespace {

struct Options {
    std::string model;
    int regions = 8;
    int views = 200;
    int size = 512;
    unsigned seed = 1;
};

void writeList(BenchJson& j, std::string_view key, const std::vector<std::size_t>& v) {
    j.beginArray(key);
    for (const std::size_t n : v) j.value(n);
    j.end();
}

int run(const Options& o) {
    if (o.regions < 1 || o.views < 1 || o.size < 16 || o.size > 8192)
        throw InputError("--regions and --views must be >= 1, --size in [16, 8192]");
    const FlatMesh model = flattenModel(parseObj(o.model));
    if (model.indices.empty()) throw InputError(o.model + ": no triangles");
    const Sphere bound = sphereAround(model.positions);
    std::vector<ViewRegion> regions = regionsAround(bound, o.regions);

    std::vector<SilhouetteRegionReport> report;
    const auto t0 = std::chrono::steady_clock::now();
    const SilhouetteMesh mesh = bakeSilhouetteMesh(model.positions, model.indices, regions, &report);
    const double bakeMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

    const auto full = mesh.indicesOf(mesh.full);
    const std::size_t trianglesFull = full.size() / 3;
    std::vector<std::size_t> reduced, baselineTris;
    MaskDifference worst, worstBaseline;
    std::size_t skipped = 0, wrongRange = 0;
    double reductionSum = 0.0;
    std::mt19937 rng(o.seed);
    CoverageMask fullMask(o.size, o.size), mask(o.size, o.size), baseMask(o.size, o.size);
    for (std::size_t r = 0; r < mesh.regions.size(); ++r) {
        const auto indices = mesh.indicesOf(mesh.ranges[r]);
        reduced.push_back(indices.size() / 3);
        reductionSum += 100.0 * (1.0 - double(indices.size() / 3) / double(trianglesFull));
        const std::vector<std::uint32_t> baseline = simplifyToTriangles(mesh.positions, full, indices.size() / 3);
        baselineTris.push_back(baseline.size() / 3);
        const Box box = mesh.regions[r].box();
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        for (int v = 0; v < o.views; ++v) {
            const glm::vec3 eye = box.min + glm::vec3(u(rng), u(rng), u(rng)) * box.size();
            if (mesh.rangeFor(eye).firstIndex != mesh.ranges[r].firstIndex) ++wrongRange;
            const float distance = glm::length(eye - bound.center);
            const float fovy = glm::degrees(2.0f * std::atan(1.1f * bound.radius / distance));
            const View view = View::lookAt(eye, bound.center, {0, 1, 0}, fovy, {o.size, o.size}, 0.05f * bound.radius,
                                           distance + 2.0f * bound.radius);
            const glm::mat4 vp = view.viewProjection();
            fullMask.clear();
            mask.clear();
            baseMask.clear();
            skipped += rasterizeCoverage(mesh.positions, full, vp, fullMask);
            skipped += rasterizeCoverage(mesh.positions, indices, vp, mask);
            skipped += rasterizeCoverage(mesh.positions, baseline, vp, baseMask);
            const MaskDifference d = compareMasks(fullMask, mask), b = compareMasks(fullMask, baseMask);
            worst.differing = std::max(worst.differing, d.differing);
            worst.differingFarFromOutline = std::max(worst.differingFarFromOutline, d.differingFarFromOutline);
            worstBaseline.differing = std::max(worstBaseline.differing, b.differing);
            worstBaseline.differingFarFromOutline =
                std::max(worstBaseline.differingFarFromOutline, b.differingFarFromOutline);
        }
        const SilhouetteRegionReport& rep = report[r];
        std::cerr << "region " << r << ": FM " << rep.front << " BM " << rep.back << " (kept " << rep.backKept
                  << ") SM " << rep.silhouette << ", triangles " << rep.trianglesBefore << " -> " << rep.trianglesAfter
                  << ", FM locked " << rep.frontLocked << ", rejected tries " << rep.rejectedTries
                  << "; worst so far: differing " << worst.differing << " far " << worst.differingFarFromOutline
                  << " | baseline " << worstBaseline.differing << " far " << worstBaseline.differingFarFromOutline
                  << "\n";
    }
    std::size_t reducedSum = 0;
    for (std::size_t n : reduced) reducedSum += n;
    const double meanReduced = double(reducedSum) / double(reduced.size());
    const double reductionMean = reductionSum / double(reduced.size());
    const bool pass = worst.differingFarFromOutline == 0 && reductionMean >= 50.0 && worstBaseline.differing > 0 &&
                      bakeMs <= 2000.0 && skipped == 0 && wrongRange == 0;
    BenchJson j;
    j.field("bench", "silhouette")
        .field("model", o.model)
        .field("regions", mesh.regions.size())
        .field("views_per_region", o.views)
        .field("mask_size", o.size)
        .field("triangles_full", trianglesFull);
    writeList(j, "triangles_reduced", reduced);
    j.field("triangles_reduced_mean", meanReduced)
        .field("reduction_pct_mean", reductionMean)
        .field("mask_pixels_differing_max", worst.differing)
        .field("mask_pixels_differing_far_from_outline_max", worst.differingFarFromOutline);
    writeList(j, "baseline_triangles", baselineTris);
    j.field("baseline_mask_pixels_differing_max", worstBaseline.differing)
        .field("baseline_mask_pixels_differing_far_from_outline_max", worstBaseline.differingFarFromOutline)
        .field("bake_ms", bakeMs)
        .field("triangles_skipped", skipped)
        .field("views_with_wrong_region", wrongRange)
        .field("targets_met", pass);
    std::cout << j.str() << std::endl;
    return kExitOk;
}

const bool registered = registerCommand(
    {"silhouette", "Silhouette-preserving reduction: masks of full vs reduced mesh", [](CommandLine& line) {
         auto o = std::make_shared<Options>();
         line.option("--model", o->model, "OBJ model").required();
         line.option("--regions", o->regions, "number of default boxes around the model");
         line.option("--views", o->views, "random viewpoints per region");
         line.option("--size", o->size, "mask width and height in pixels");
         line.option("--seed", o->seed, "random seed for the viewpoints");
         return [o] { return run(*o); };
     }});

}  // namespace

}  // namespace arcomp
