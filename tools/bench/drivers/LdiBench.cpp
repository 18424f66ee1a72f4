// `arcomp-bench ldi`: translucent point clouds from several LDIs (DESIGN.md
// section 5). A procedural tree is voxelized at 200^3 and drawn at 512x512
// from a camera circling it, with 1, 3, 5 and 7 LDIs, each frame compared
// with the depth-sorted reference (the baseline, same run, same splats).
// Then the paper's red/black test for 1 and 6 LDIs, and a PNG strip
// (reference | 1 LDI | 6 LDIs) of one view in --out.
//
//   arcomp-bench ldi --out build/bench-ldi
//
// A pixel counts as wrong when any premultiplied RGBA8 channel differs from
// the reference by more than kTolerance levels; the share is taken over the
// pixels either image covers, summed over all frames.
//
// Times: render_ms_per_frame is the wall-clock median (the figure);
// render_min_ms the fastest frame; render_cpu_ms_per_frame the median CPU
// time of the process over the frame (all threads), which a machine shared
// with other busy users inflates far less than wall time. order_ms_per_frame
// is the part of the frame spent ordering the points (the McMillan walks;
// for the reference, depth_sort_order_ms_per_frame, its sort): the rest,
// projection and splatting, is the same work in both. build_s is the
// registration into the LDIs (the paper's "LDI generation"), not the
// voxelization.

#include "graph/core/ElapsedTime.hpp"
#include "graph/points/LdiRenderer.hpp"
#include "graph/points/Voxelizer.hpp"
#include "graph/scenes/ProceduralTree.hpp"
#include "tools/bench/report/BenchJson.hpp"
#include "tools/bench/report/Stats.hpp"
#include "tools/cli/Command.hpp"

#include <glm/gtc/constants.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

namespace arcomp {

namespace {

constexpr int kTolerance = 8;

using Clock = std::chrono::steady_clock;

// --- Measuring ------------------------------------------------------------

View circlingView(const Sphere& bound, int frame, int frames, int size) {
    const float a = glm::two_pi<float>() * static_cast<float>(frame) / static_cast<float>(frames);
    const float distance = bound.radius * 2.6f;
    const glm::vec3 eye = bound.center + glm::vec3(std::sin(a), 0.35f, std::cos(a)) * distance;
    return View::lookAt(eye, bound.center, {0, 1, 0}, 45.0f, {size, size}, distance * 0.1f, distance * 3.0f);
}

struct Difference {
    std::size_t wrong = 0, covered = 0;
    double pct() const { return covered ? 100.0 * static_cast<double>(wrong) / static_cast<double>(covered) : 0.0; }
};

void compare(const PointImage& a, const PointImage& b, Difference& d) {
    for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
        if (a.rgba[i + 3] == 0 && b.rgba[i + 3] == 0) continue;
        ++d.covered;
        for (int c = 0; c < 4; ++c)
            if (std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c])) > kTolerance) {
                ++d.wrong;
                break;
            }
    }
}

// Over white, for people to look at.
void pasteOnWhite(cv::Mat& strip, int column, const PointImage& img) {
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const std::uint8_t* p = &img.rgba[static_cast<std::size_t>(y * img.width + x) * 4];
            cv::Vec3b& out = strip.at<cv::Vec3b>(y, column * img.width + x);
            for (int c = 0; c < 3; ++c) out[2 - c] = static_cast<std::uint8_t>(std::min(255, p[c] + 255 - p[3]));
        }
}

struct Options {
    std::string out = "bench-ldi";
    int frames = 24;
    int resolution = 200;
    int size = 512;
    int threads = 2;
};

struct Measured {
    int ldis;
    double buildS, renderMs, renderMinMs, renderCpuMs, orderMs, wrongPct;
    std::size_t splats;
};

int benchLdi(const Options& o) {
    if (o.frames < 1 || o.size < 16 || o.threads < 1)
        throw InputError("--frames, --size and --threads must be positive");
    std::filesystem::create_directories(o.out);
    const ProceduralTree tree = growTree(2009);
    const std::vector<VoxelSource> sources = tree.voxelSources();
    auto t0 = Clock::now();
    const VoxelGrid grid = voxelize(sources, o.resolution);
    const double voxelizeS = msSince(t0) / 1000.0;
    const PointCloud cloud = pointCloudFromVoxels(grid);
    const Sphere bound = sphereAround(cloud.positions);
    std::fprintf(stderr, "tree: %zu + %zu triangles -> %zu voxels at %d^3 in %.2f s\n", tree.wood.triangleCount(),
                 tree.leaves.triangleCount(), grid.size(), o.resolution, voxelizeS);

    const std::vector<int> counts = {1, 3, 5, 7};
    std::vector<LdiSet> sets;
    std::vector<Measured> measured;
    for (int n : counts) {
        t0 = Clock::now();
        sets.push_back(buildLdis(cloud, ldiCamerasAround(bound, n, cloud.pointSize)));
        measured.push_back({n, msSince(t0) / 1000.0, 0, 0, 0, 0, 0, 0});
        std::fprintf(stderr, "%d LDIs built in %.3f s (%zu points unregistered)\n", n, measured.back().buildS,
                     sets.back().unregistered);
    }
    LdiRenderer reference(sets[0], o.threads);
    std::vector<std::unique_ptr<LdiRenderer>> renderers;
    for (const LdiSet& s : sets) renderers.push_back(std::make_unique<LdiRenderer>(s, o.threads));
    std::vector<std::vector<double>> times(counts.size()), cpuTimes(counts.size()), orderTimes(counts.size());
    std::vector<double> sortTimes, sortCpuTimes, sortOrderTimes;
    std::vector<Difference> diffs(counts.size());
    reference.renderDepthSorted(circlingView(bound, 0, o.frames, o.size));  // warm the buffers
    for (auto& r : renderers) r->render(circlingView(bound, 0, o.frames, o.size));
    for (int f = 0; f < o.frames; ++f) {
        const View view = circlingView(bound, f, o.frames, o.size);
        t0 = Clock::now();
        double c0 = processCpuMs();
        const PointImage& ref = reference.renderDepthSorted(view);
        sortCpuTimes.push_back(processCpuMs() - c0);
        sortTimes.push_back(msSince(t0));
        sortOrderTimes.push_back(reference.lastOrderMs());
        for (std::size_t i = 0; i < counts.size(); ++i) {
            t0 = Clock::now();
            c0 = processCpuMs();
            const PointImage& img = renderers[i]->render(view);
            cpuTimes[i].push_back(processCpuMs() - c0);
            times[i].push_back(msSince(t0));
            orderTimes[i].push_back(renderers[i]->lastOrderMs());
            compare(img, ref, diffs[i]);
            measured[i].splats = renderers[i]->lastSplatCount();
        }
        std::fprintf(stderr, "\rframe %d/%d", f + 1, o.frames);
    }
    std::fprintf(stderr, "\n");
    const double sortMs = median(sortTimes), sortMinMs = *std::min_element(sortTimes.begin(), sortTimes.end());
    const double sortCpuMs = median(sortCpuTimes), sortOrderMs = median(sortOrderTimes);
    for (std::size_t i = 0; i < counts.size(); ++i) {
        measured[i].renderMs = median(times[i]);
        measured[i].renderMinMs = *std::min_element(times[i].begin(), times[i].end());
        measured[i].renderCpuMs = median(cpuTimes[i]);
        measured[i].orderMs = median(orderTimes[i]);
        measured[i].wrongPct = diffs[i].pct();
    }

    // The paper's two-colour test: red and black by position (3D checker of
    // 6-voxel blocks), same alphas, so that a point drawn out of order shows.
    PointCloud redBlack = cloud;
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const glm::u16vec3 c = grid.cells[i];
        const bool red = ((c.x / 6) + (c.y / 6) + (c.z / 6)) % 2 == 0;
        redBlack.colors[i] = glm::vec4(red ? 0.9f : 0.0f, 0.0f, 0.0f, cloud.colors[i].a);
    }
    const LdiSet rb1 = buildLdis(redBlack, ldiCamerasAround(bound, 1, cloud.pointSize));
    const LdiSet rb6 = buildLdis(redBlack, ldiCamerasAround(bound, 6, cloud.pointSize));
    LdiRenderer rbRef(rb1, o.threads), rbOne(rb1, o.threads), rbSix(rb6, o.threads);
    Difference rbDiff1, rbDiff6;
    for (int f = 0; f < o.frames; ++f) {
        const View view = circlingView(bound, f, o.frames, o.size);
        const PointImage& ref = rbRef.renderDepthSorted(view);
        compare(rbOne.render(view), ref, rbDiff1);
        compare(rbSix.render(view), ref, rbDiff6);
    }

    // Strips of one view, an eighth of the way round (between the front LDI
    // and the side ones).
    const View stripView = circlingView(bound, 1, 8, o.size);
    const LdiSet six = buildLdis(cloud, ldiCamerasAround(bound, 6, cloud.pointSize));
    LdiRenderer sixRenderer(six, o.threads);
    std::vector<std::string> written;
    for (int pass = 0; pass < 2; ++pass) {
        LdiRenderer& ref = pass == 0 ? reference : rbRef;
        LdiRenderer& one = pass == 0 ? *renderers[0] : rbOne;
        LdiRenderer& many = pass == 0 ? sixRenderer : rbSix;
        cv::Mat strip(o.size, o.size * 3, CV_8UC3);
        pasteOnWhite(strip, 0, ref.renderDepthSorted(stripView));
        pasteOnWhite(strip, 1, one.render(stripView));
        pasteOnWhite(strip, 2, many.render(stripView));
        const std::string file =
            (std::filesystem::path(o.out) / (pass == 0 ? "ldi_strip.png" : "ldi_strip_redblack.png")).string();
        if (!cv::imwrite(file, strip)) throw std::runtime_error(file + ": cannot write");
        written.push_back(file);
    }

    const Measured& seven = measured.back();
    // Issue #23: the 7-LDI frame at least twice as fast as the depth-sorted
    // one, and the paper's claim, its ordering at least five times as fast
    // as the sort. Both against the reference of the same run, not a fixed
    // number of milliseconds.
    const bool renderOk = sortMs >= 2.0 * seven.renderMs;
    const bool orderOk = sortOrderMs >= 5.0 * seven.orderMs;
    const bool buildOk = seven.buildS <= 1.0;
    const bool redBlackOk = rbDiff6.pct() < rbDiff1.pct();
    // Every figure to three places, as this bench has always reported them.
    const auto rounded = [](double x) { return Fixed{x, 3}; };
    BenchJson json;
    json.field("bench", "ldi")
        .field("voxels", grid.size())
        .field("grid", o.resolution)
        .field("output", std::to_string(o.size) + "x" + std::to_string(o.size))
        .field("frames", o.frames)
        .field("threads", o.threads)
        .field("tolerance_levels", kTolerance)
        .field("depth_sort_ms_per_frame", rounded(sortMs))
        .field("depth_sort_min_ms", rounded(sortMinMs))
        .field("depth_sort_cpu_ms_per_frame", rounded(sortCpuMs))
        .field("depth_sort_order_ms_per_frame", rounded(sortOrderMs));
    json.beginArray("ldi");
    for (const Measured& m : measured)
        json.beginObject()
            .field("ldis", m.ldis)
            .field("build_s", rounded(m.buildS))
            .field("render_ms_per_frame", rounded(m.renderMs))
            .field("render_min_ms", rounded(m.renderMinMs))
            .field("render_cpu_ms_per_frame", rounded(m.renderCpuMs))
            .field("speedup_vs_depth_sort", rounded(sortMs / m.renderMs))
            .field("order_ms_per_frame", rounded(m.orderMs))
            .field("order_speedup_vs_depth_sort", rounded(sortOrderMs / m.orderMs))
            .field("wrong_pixels_pct", rounded(m.wrongPct))
            .field("splats", m.splats)
            .end();
    json.end();
    json.beginObject("red_black")
        .field("wrong_pixels_pct_1_ldi", rounded(rbDiff1.pct()))
        .field("wrong_pixels_pct_6_ldis", rounded(rbDiff6.pct()))
        .end();
    json.beginObject("targets")
        .field("render_7_ge_2x_faster", renderOk)
        .field("order_7_ge_5x_faster", orderOk)
        .field("build_7_le_1s", buildOk)
        .field("wrong_6_lt_1", redBlackOk)
        .end();
    json.beginArray("strips").value(written[0]).value(written[1]).end();
    std::printf("%s\n", json.str().c_str());
    return kExitOk;
}

const bool registered = registerCommand(
    {"ldi", "Translucent point clouds: McMillan order over 1-7 LDIs vs depth sort", [](CommandLine& line) {
         auto o = std::make_shared<Options>();
         line.option("--out", o->out, "folder for the PNG strips").showDefault();
         line.option("--frames", o->frames, "views on the circle").showDefault();
         line.option("--res", o->resolution, "voxel grid resolution").showDefault();
         line.option("--size", o->size, "output width and height").showDefault();
         line.option("--threads", o->threads, "renderer threads").showDefault();
         return [o] { return benchLdi(*o); };
     }});

}  // namespace

}  // namespace arcomp
