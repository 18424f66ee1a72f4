// arcomp-bench cull: the select traversal (cull + LOD + draw-list build) on
// the scene of CullScene.hpp, timed against OpenSceneGraph's CullVisitor on
// the same scene in the same run where OpenSceneGraph is available, the two
// sides taking turns a block of frames at a time.
//
// One JSON line: per side, the median, 95th percentile, minimum and maximum
// frame time over the measured frames (a median alone hides the frames a
// station would drop), the median visible count and the LOD level counts;
// then whether every frame's counts match OpenSceneGraph's and the ratio of
// the two medians (speedup_vs_osg) and of the two 95th percentiles.

#include "graph/core/SelectPass.hpp"
#include "graph/lod/Lod.hpp"
#include "tools/bench/drivers/CullBenchOsg.hpp"
#include "tools/bench/report/BenchJson.hpp"
#include "tools/bench/report/Stats.hpp"
#include "tools/bench/scenes/CullScene.hpp"
#include "tools/cli/Command.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <utility>

namespace arcomp {

namespace {

constexpr int kWarmupFrames = 20;
// Frames a side is timed in one turn, and the untimed ones that start each
// later turn.
constexpr int kBlockFrames = 20;
constexpr int kBlockWarmupFrames = 2;

struct ArcompCullScene {
    World world;
    Scene& scene = world.scene;
    LodTable& lods = world.lods;
    std::uint32_t levelGeometry[3] = {};
};

void addGroup(ArcompCullScene& out, const CullScene& s, std::uint32_t group, NodeId parent, const MeshPart* parts) {
    const CullGroup& g = s.groups[group];
    for (std::uint32_t k : g.objects) {
        const NodeId t = out.scene.addTransform(parent, glm::translate(glm::mat4(1.0f), s.positions[k]));
        LodNode lod;
        lod.setThresholds({kCullRanges[0], kCullRanges[1]});
        lod.hysteresis = 0.0f;  // OpenSceneGraph's ranges have none; counts must match
        const NodeId l = out.scene.addNode(t, NodeKind::Lod, out.lods.add(lod));
        for (int level = 0; level < 3; ++level) out.scene.addMesh(l, parts[level]);
    }
    for (std::uint32_t child : g.groups) addGroup(out, s, child, out.scene.addGroup(parent), parts);
}

void build(ArcompCullScene& out, const CullScene& s) {
    const std::uint32_t material = out.scene.addMaterial({});
    MeshPart parts[3];
    for (int level = 0; level < 3; ++level) {
        out.levelGeometry[level] =
            out.scene.addGeometry(makeUvSphere(1.0f, kCullSphereSlices[level], kCullSphereStacks[level]));
        parts[level] = {out.levelGeometry[level], material};
    }
    addGroup(out, s, 0, out.scene.root(), parts);
    out.scene.update();
}

View cameraView(const CullScene& s, int frame, int frames) {
    const CullCamera c = cullCamera(s, frame, frames);
    return View::lookAt(c.eye, c.target, {0, 1, 0}, kCullFovyDegrees, {kCullWidth, kCullHeight}, kCullNear, kCullFar);
}

// One select of frame `frame` of `frames`: its wall milliseconds and what it found.
std::pair<double, CullFrameCounts> arcompFrame(ArcompCullScene& a, const CullScene& s, DrawList& list, int frame,
                                               int frames) {
    const View view = cameraView(s, frame, frames);
    const SelectSettings settings{.timeSeconds = frame / 60.0};
    const auto start = std::chrono::steady_clock::now();
    select(a.world, view, settings, list);
    const auto stop = std::chrono::steady_clock::now();
    CullFrameCounts counts;
    counts.visible = static_cast<std::uint32_t>(list.items.size());
    for (const DrawItem& item : list.items) ++counts.levels[std::min<int>(item.level, 2)];
    return {std::chrono::duration<double, std::milli>(stop - start).count(), counts};
}

// Frames [first, last) of the path on one side, after `warmup` untimed
// frames that bring that side's data back into cache; `cull(frame)` culls
// one frame and returns its time and counts.
template <class Cull>
void timeBlock(CullRun& run, int first, int last, int warmup, Cull&& cull) {
    for (int f = 0; f < warmup; ++f) cull(first);
    for (int f = first; f < last; ++f) {
        const auto [ms, counts] = cull(f);
        run.msPerFrame.push_back(ms);
        run.counts.push_back(counts);
    }
}

struct Summary {
    double medianMs = 0, p95Ms = 0, minMs = 0, maxMs = 0;
    double visibleMedian = 0;
    std::uint64_t levels[3] = {0, 0, 0};
};

Summary summarize(const CullRun& run) {
    Summary s;
    s.medianMs = median(run.msPerFrame);
    s.p95Ms = percentile(run.msPerFrame, 95);
    s.minMs = *std::min_element(run.msPerFrame.begin(), run.msPerFrame.end());
    s.maxMs = *std::max_element(run.msPerFrame.begin(), run.msPerFrame.end());
    std::vector<double> visible;
    for (const CullFrameCounts& c : run.counts) {
        visible.push_back(c.visible);
        for (int l = 0; l < 3; ++l) s.levels[l] += c.levels[l];
    }
    s.visibleMedian = median(visible);
    return s;
}

int runCullBench(std::uint32_t objects, const std::string& layoutName, int frames) {
    if (frames < 1) throw InputError("--frames must be at least 1");
    if (objects < 1) throw InputError("--objects must be at least 1");
    if (layoutName != "flat" && layoutName != "tree")
        throw InputError("--layout must be flat or tree, not " + layoutName);
    const CullLayout layout = layoutName == "flat" ? CullLayout::Flat : CullLayout::Tree;
    const CullScene description = makeCullScene(objects, layout);

    std::cerr << "cull: building " << objects << " objects (" << layoutName << ")\n";
    ArcompCullScene scene;
    build(scene, description);
    DrawList list;
    const auto ours = [&](int f) { return arcompFrame(scene, description, list, f, frames); };
    CullRun ourRun;
#ifdef ARCOMP_HAVE_OSG
    OsgCull osgCull(description);
    const auto osg = [&](int f) { return osgCull.frame(f, frames); };
    CullRun osgRun;
    // The two sides take turns, a block of frames each, so that both are
    // timed through the same spells of the machine: on a shared one, a core
    // has run 1.6x slower than its sibling for minutes at a time, and a
    // process moved between the two sides' runs would carry that into
    // their ratio.
    std::cerr << "cull: " << scene.scene.nodeCount()
              << " nodes; timing arcomp and OpenSceneGraph CullVisitor in turns\n";
    for (int first = 0; first < frames; first += kBlockFrames) {
        const int last = std::min(frames, first + kBlockFrames);
        const int warmup = first == 0 ? kWarmupFrames : kBlockWarmupFrames;
        timeBlock(ourRun, first, last, warmup, ours);
        timeBlock(osgRun, first, last, warmup, osg);
    }
#else
    std::cerr << "cull: " << scene.scene.nodeCount() << " nodes; timing arcomp\n";
    timeBlock(ourRun, 0, frames, kWarmupFrames, ours);
#endif
    const Summary s = summarize(ourRun);

    BenchJson json;
    const auto levelCounts = [&json](const char* key, const Summary& summary) {
        json.beginArray(key).value(summary.levels[0]).value(summary.levels[1]).value(summary.levels[2]).end();
    };
    json.field("bench", "cull")
        .field("objects", objects)
        .field("layout", layoutName)
        .field("frames", frames)
        .field("measured_frames", ourRun.msPerFrame.size())
        .field("warmup_frames", kWarmupFrames)
        .field("ms_per_frame_median", s.medianMs)
        .field("ms_per_frame_p95", s.p95Ms)
        .field("ms_per_frame_min", s.minMs)
        .field("ms_per_frame_max", s.maxMs)
        .field("ns_per_object_median", s.medianMs * 1e6 / objects)
        .field("visible_median", s.visibleMedian);
    levelCounts("lod_level_counts", s);
    json.field("nodes", scene.scene.nodeCount())
        .field("block_frames", kBlockFrames)
        .field("block_warmup_frames", kBlockWarmupFrames);
#ifdef ARCOMP_HAVE_OSG
    const Summary o = summarize(osgRun);
    std::size_t mismatched = 0;
    for (std::size_t f = 0; f < ourRun.counts.size(); ++f) mismatched += ourRun.counts[f] == osgRun.counts[f] ? 0 : 1;
    json.field("osg_measured_frames", osgRun.msPerFrame.size())
        .field("osg_ms_per_frame_median", o.medianMs)
        .field("osg_ms_per_frame_p95", o.p95Ms)
        .field("osg_ms_per_frame_min", o.minMs)
        .field("osg_ms_per_frame_max", o.maxMs)
        .field("osg_visible_median", o.visibleMedian);
    levelCounts("osg_lod_level_counts", o);
    json.field("frames_with_count_mismatch", mismatched)
        .field("counts_match_osg", mismatched == 0)
        .field("speedup_vs_osg", s.medianMs > 0 ? o.medianMs / s.medianMs : 0.0)
        .field("speedup_vs_osg_p95", s.p95Ms > 0 ? o.p95Ms / s.p95Ms : 0.0);
#else
    json.field("osg", "not built (OpenSceneGraph not found)");
#endif
    std::cout << json.str() << std::endl;
    return kExitOk;
}

const bool registered =
    registerCommand({"cull", "Select traversal (cull + LOD + draw list) against OpenSceneGraph", [](CommandLine& line) {
                         auto objects = std::make_shared<std::uint32_t>(100000);
                         auto layout = std::make_shared<std::string>("flat");
                         auto frames = std::make_shared<int>(200);
                         line.option("--objects", *objects, "Number of objects").showDefault();
                         line.option("--layout", *layout, "flat or tree").showDefault();
                         line.option("--frames", *frames, "Measured frames (after 20 warm-up frames)").showDefault();
                         return [=] { return runCullBench(*objects, *layout, *frames); };
                     }});

}  // namespace

}  // namespace arcomp
