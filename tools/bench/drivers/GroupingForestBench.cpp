// arcomp-bench grouping-forest --out DIR: the grouping paper's experiment
// (DESIGN.md §2, Fig. 9-11). 32 trees of 105 triangles seen from a fixed
// viewpoint; for Ωt from 0.001 to 0.1 in steps of 0.001 the triangles drawn
// with full detail, simplification only, and grouping + simplification,
// for the mixed (5 red) and the all-green forest. Writes forest.csv and
// forest.png (the paper's Fig. 10), renders both forests full and grouped
// and reports the grouped images' PSNR against the full ones. Baseline in
// the same run: simplification alone.

#include "graph/scenes/ForestExperiment.hpp"
#include "runtime/gl/GlContext.hpp"
#include "runtime/gl/RenderTarget.hpp"
#include "runtime/render/ImpostorBaker.hpp"
#include "runtime/render/Renderer.hpp"
#include "runtime/station/ImageFile.hpp"
#include "tools/bench/report/BenchJson.hpp"
#include "tools/bench/report/ImageDifference.hpp"
#include "tools/bench/report/LinePlot.hpp"
#include "tools/cli/CliParse.hpp"
#include "tools/cli/Command.hpp"

#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>

namespace arcomp {

namespace {

struct Options {
    std::string out;
    std::string size = "960x540";
    float omegaT = 0.011f;  // the paper's Fig. 9 and 11
};

struct Curve {
    std::vector<double> full, simplified, grouped;
};

const glm::vec4 kSky{0.62f, 0.72f, 0.82f, 1.0f};

int run(const Options& o) {
    if (o.out.empty()) throw InputError("--out: a folder is required");
    if (!(o.omegaT > 0.0f && o.omegaT < 1.0f)) throw InputError("--omega-t: expected a number in (0, 1)");
    const glm::ivec2 size = parseSize(o.size, "--size");
    const std::filesystem::path dir(o.out);
    std::filesystem::create_directories(dir);

    const GroupingParams params;
    std::vector<double> thresholds;
    for (int k = 0; k < params.stepCount(); ++k) thresholds.push_back(params.thresholdAt(k));

    ForestExperiment mixed(ForestColouring::Mixed, params, size), green(ForestColouring::Green, params, size);
    Curve curves[2];
    ForestExperiment* forests[2] = {&mixed, &green};
    for (int f = 0; f < 2; ++f)
        for (double t : thresholds) {
            curves[f].full.push_back(double(forests[f]->triangles(ForestMode::Full, float(t))));
            curves[f].simplified.push_back(double(forests[f]->triangles(ForestMode::Simplified, float(t))));
            curves[f].grouped.push_back(double(forests[f]->triangles(ForestMode::Grouped, float(t))));
        }

    std::ofstream csv(dir / "forest.csv");
    csv << "omega_t,mixed_full,mixed_simplified,mixed_grouped,green_full,green_simplified,green_grouped\n";
    for (std::size_t i = 0; i < thresholds.size(); ++i)
        csv << thresholds[i] << ',' << curves[0].full[i] << ',' << curves[0].simplified[i] << ','
            << curves[0].grouped[i] << ',' << curves[1].full[i] << ',' << curves[1].simplified[i] << ','
            << curves[1].grouped[i] << '\n';
    if (!csv) throw std::runtime_error((dir / "forest.csv").string() + ": cannot write");

    LinePlot plot("Triangles drawn against Omega_t (paper Fig. 10)", "Omega_t", "triangles");
    plot.addSeries("simplification only", thresholds, curves[0].simplified);
    plot.addSeries("grouping + simplification, 5 red", thresholds, curves[0].grouped);
    plot.addSeries("grouping + simplification, all green", thresholds, curves[1].grouped);
    plot.addLevel("full detail", curves[0].full.front());
    plot.writePng(dir / "forest.png");

    // First Ωt from which grouping stays below simplification alone.
    double helpsFrom[2] = {-1.0, -1.0};
    for (int f = 0; f < 2; ++f)
        for (std::size_t i = thresholds.size(); i-- > 0;) {
            if (curves[f].grouped[i] >= curves[f].simplified[i]) break;
            helpsFrom[f] = thresholds[i];
        }

    // Renders at the chosen Ωt: full detail, simplification, grouping with
    // box proxies and with baked impostors.
    std::cerr << "rendering " << size.x << "x" << size.y << "\n";
    auto context = HeadlessContext::create(GlRequest::Auto);
    RenderTarget target(size);
    double psnrBox[2] = {0, 0}, psnrImpostor[2] = {0, 0}, psnrSimplified[2] = {0, 0};
    std::size_t trianglesAt[2][3] = {};
    const char* names[2] = {"mixed", "green"};
    for (int f = 0; f < 2; ++f) {
        ForestExperiment& e = *forests[f];
        const std::size_t baked = bakeImpostors(e.world.scene, e.forest.grouping, e.world.grouping,
                                                {.pixelsPerUnit = 0.6f, .eye = e.view.eye});
        std::cerr << names[f] << ": " << baked << " impostors baked\n";
        Renderer renderer;
        const auto shot = [&](ForestMode mode, GroupingProxy proxy, const char* label) {
            const DrawList& list = e.select(mode, o.omegaT, proxy);
            target.bind();
            renderer.draw(e.world.scene, list, e.view, {.clearColor = kSky});
            Image img = target.read();
            writePng(dir / (std::string("forest-") + names[f] + "-" + label + ".png"), img);
            return std::pair{img, drawnTriangles(e.world.scene, list)};
        };
        const auto [full, fullTris] = shot(ForestMode::Full, GroupingProxy::Box, "full");
        const auto [simple, simpleTris] = shot(ForestMode::Simplified, GroupingProxy::Box, "simplified");
        const auto [box, boxTris] = shot(ForestMode::Grouped, GroupingProxy::Box, "grouped-box");
        const auto [imp, impTris] = shot(ForestMode::Grouped, GroupingProxy::Impostor, "grouped-impostor");
        psnrSimplified[f] = psnr(full, simple);
        psnrBox[f] = psnr(full, box);
        psnrImpostor[f] = psnr(full, imp);
        trianglesAt[f][0] = fullTris;
        trianglesAt[f][1] = simpleTris;
        trianglesAt[f][2] = boxTris;
        (void)impTris;
    }

    // Ωt lies on GroupingParams' 0.001 grid, summed in float steps: more
    // decimals than the grid's would print their rounding.
    const auto onGrid = [](double t) { return Fixed{t, 3}; };
    BenchJson j;
    j.field("bench", "grouping-forest")
        .field("omega_t_steps", thresholds.size())
        .field("full_triangles", curves[0].full.front());
    j.beginObject("grouping_helps_from_omega_t")
        .field("mixed", onGrid(helpsFrom[0]))
        .field("green", onGrid(helpsFrom[1]))
        .end();
    j.beginObject("triangles_at_omega_t_0_1")
        .field("mixed_simplified", curves[0].simplified.back())
        .field("mixed_grouped", curves[0].grouped.back())
        .field("green_grouped", curves[1].grouped.back())
        .end();
    j.field("render_omega_t", o.omegaT);
    j.beginObject("render_triangles");
    for (int f = 0; f < 2; ++f)
        j.beginObject(names[f])
            .field("full", trianglesAt[f][0])
            .field("simplified", trianglesAt[f][1])
            .field("grouped", trianglesAt[f][2])
            .end();
    j.end();
    // Identical images have no PSNR (infinite): null.
    j.beginObject("psnr_db_vs_full");
    for (int f = 0; f < 2; ++f)
        j.field(std::string(names[f]) + "_simplified", psnrSimplified[f])
            .field(std::string(names[f]) + "_grouped_box", psnrBox[f])
            .field(std::string(names[f]) + "_grouped_impostor", psnrImpostor[f]);
    j.end();
    j.field("csv", (dir / "forest.csv").string()).field("plot", (dir / "forest.png").string());
    std::cout << j.str() << "\n";
    return kExitOk;
}

const bool registered = registerCommand(
    {"grouping-forest", "Grouping paper's forest: triangles against Omega_t (CSV, PNG), renders and PSNR",
     [](CommandLine& line) {
         auto o = std::make_shared<Options>();
         line.option("--out", o->out, "Folder for forest.csv, forest.png and the renders").required();
         line.option("--size", o->size, "Render size WIDTHxHEIGHT").showDefault();
         line.option("--omega-t", o->omegaT, "Omega_t of the renders").showDefault();
         return [o] { return run(*o); };
     }});

}  // namespace
}  // namespace arcomp
