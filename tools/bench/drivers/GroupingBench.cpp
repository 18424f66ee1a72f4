// arcomp-bench grouping --objects N: how the grouping tree scales
// (DESIGN.md §2). N objects on a jittered plantation grid (sizes, colours
// and offsets from a seeded generator) under one grouping node; reports
// the tree's build time and depth, the select pass along a camera path
// (baseline in the same run: the same pass without grouping), and the
// local rebuild with 1% of the objects moving every frame.
//
// Targets (issue 4): build < 1 s at 10,000 objects and < 20 s at 100,000;
// select <= 2 ms a frame and rebuild <= 5 ms a frame at 100,000.

#include "graph/core/ElapsedTime.hpp"
#include "graph/core/SelectPass.hpp"
#include "graph/grouping/GroupingNodes.hpp"
#include "tools/bench/report/BenchJson.hpp"
#include "tools/cli/Command.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <random>

namespace arcomp {

namespace {

struct Options {
    std::size_t objects = 10000;
    int frames = 120;
    unsigned seed = 1;
};

using Clock = std::chrono::steady_clock;

constexpr float kSpacing = 200.0f;  // cm between grid points
constexpr float kFrameSeconds = 1.0f / 30.0f;

int run(const Options& o) {
    if (o.objects < 2 || o.objects > 2'000'000) throw InputError("--objects: expected 2 .. 2000000");
    if (o.frames < 1) throw InputError("--frames: expected >= 1");
    std::mt19937 rng(o.seed);
    std::uniform_real_distribution<float> jitter(-12.0f, 12.0f), unit(0.0f, 1.0f), tint(-0.03f, 0.03f);
    std::uniform_int_distribution<int> kind(0, 2);
    const glm::vec3 palette[3] = {{0.1f, 0.5f, 0.1f}, {0.15f, 0.45f, 0.1f}, {0.7f, 0.2f, 0.1f}};
    const float edges[3] = {180.0f, 200.0f, 220.0f};

    World world;
    Scene& scene = world.scene;
    GroupingNodes& table = world.grouping;
    const NodeId grouping = addGroupingNode(scene, scene.root(), table, "field");
    std::uint32_t boxes[3], materials[9];
    for (int k = 0; k < 3; ++k) boxes[k] = scene.addGeometry(makeBox({edges[k], 300.0f, edges[k]}));
    for (int k = 0; k < 9; ++k) {
        Material m;
        m.baseColor = glm::vec4(palette[k % 3] + glm::vec3(0.01f * float(k / 3)), 1.0f);
        materials[k] = scene.addMaterial(m);
    }
    const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(double(o.objects))));
    std::vector<NodeId> places;
    std::vector<GroupingItem> items;
    places.reserve(o.objects);
    items.reserve(o.objects);
    for (std::size_t i = 0; i < o.objects; ++i) {
        const glm::vec3 at{float(i % side) * kSpacing + jitter(rng), 150.0f, float(i / side) * kSpacing + jitter(rng)};
        const int size = kind(rng), colour = kind(rng) + 3 * kind(rng);
        const NodeId place = scene.addTransform(grouping, glm::translate(glm::mat4(1.0f), at));
        scene.addMesh(place, {boxes[size], materials[colour]});
        places.push_back(place);
    }
    scene.update();
    std::cerr << "grouping " << o.objects << " objects\n";

    // Build: the objects as the measure sees them, then the tree.
    const auto t0 = Clock::now();
    GroupingParams params;
    buildGrouping(scene, grouping, table, params);
    const double buildMs = msSince(t0);
    GroupingNode& node = table.nodes[scene.payload(grouping)];
    GroupingTree& tree = node.tree;
    std::size_t groups = 0;
    for (std::uint32_t n = 0; n < tree.nodeCount(); ++n) groups += tree.alive(n) && !tree.isLeaf(n);

    // Select along a path over the field, 15 m up, looking ahead and down.
    const float extent = float(side) * kSpacing;
    const auto viewAt = [&](int f) {
        const float s = float(f) / float(std::max(1, o.frames - 1));
        const glm::vec3 eye{extent * (0.1f + 0.8f * s), 1500.0f, extent * (0.1f + 0.3f * s)};
        return View::lookAt(eye, eye + glm::vec3(0.6f, -0.25f, 1.0f), {0, 1, 0}, 60.0f, {1280, 720}, 10.0f,
                            4.0f * extent);
    };
    DrawList list;
    double selectMs = 0.0, ungroupedMs = 0.0;
    std::size_t drawn = 0, drawnUngrouped = 0, visited = 0;
    for (int f = 0; f < o.frames; ++f) {
        const View v = viewAt(f);
        auto t = Clock::now();
        select(world, v, {}, list);
        selectMs += msSince(t);
        drawn += list.items.size();
        visited += list.nodesVisited;
        t = Clock::now();
        select(world, v, {.grouping = false}, list);
        ungroupedMs += msSince(t);
        drawnUngrouped += list.items.size();
    }

    // 1% of the objects drift each frame, each with its own velocity; the
    // scene's transforms and the tree's boxes follow.
    const std::size_t moving = std::max<std::size_t>(1, o.objects / 100);
    std::vector<std::uint32_t> movers;
    std::vector<glm::vec3> velocity;
    std::uniform_int_distribution<std::size_t> pick(0, o.objects - 1);
    for (std::size_t k = 0; k < moving; ++k) {
        movers.push_back(static_cast<std::uint32_t>(pick(rng)));
        const float a = unit(rng) * 6.2831853f;
        velocity.push_back(glm::vec3(std::cos(a), 0.0f, std::sin(a)) * (50.0f + 150.0f * unit(rng)));
    }
    double rebuildMs = 0.0;
    GroupingRebuildStats total;
    for (int f = 0; f < o.frames; ++f) {
        for (std::size_t k = 0; k < movers.size(); ++k) {
            const std::uint32_t m = movers[k];
            const glm::vec3 d = velocity[k] * kFrameSeconds;
            Box b = tree.item(m).box;
            b.min += d;
            b.max += d;
            tree.moveObject(m, b, velocity[k]);
            scene.setLocal(places[m], glm::translate(scene.local(places[m]), d));
        }
        const auto t = Clock::now();
        const GroupingRebuildStats s = tree.rebuildMoved();
        rebuildMs += msSince(t);
        total.refitted += s.refitted;
        total.dissolved += s.dissolved;
        total.merged += s.merged;
        scene.update();
    }

    const double frames = double(o.frames);
    const bool big = o.objects >= 100000;
    const double buildTarget = big ? 20000.0 : 1000.0;
    BenchJson j;
    j.field("bench", "grouping")
        .field("objects", o.objects)
        .field("build_ms", buildMs)
        .field("tree_depth", tree.depth())
        .field("groups", groups)
        .field("top_level", tree.roots().size())
        .field("frames", o.frames)
        .field("select_ms_per_frame", selectMs / frames)
        .field("drawn_items_per_frame", double(drawn) / frames)
        .field("visited_nodes_per_frame", double(visited) / frames)
        .field("baseline_ungrouped_select_ms_per_frame", ungroupedMs / frames)
        .field("baseline_ungrouped_items_per_frame", double(drawnUngrouped) / frames)
        .field("moving_per_frame", moving)
        .field("rebuild_ms_per_frame", rebuildMs / frames)
        .field("refitted_per_frame", double(total.refitted) / frames)
        .field("dissolved_per_frame", double(total.dissolved) / frames)
        .field("merged_per_frame", double(total.merged) / frames);
    j.beginObject("targets")
        .field("build_ms", buildTarget)
        .field("select_ms_per_frame", 2)
        .field("rebuild_ms_per_frame", 5)
        .end();
    j.field("build_within_target", buildMs < buildTarget)
        .field("select_within_target", selectMs / frames <= 2.0)
        .field("rebuild_within_target", rebuildMs / frames <= 5.0);
    std::cout << j.str() << "\n";
    return kExitOk;
}

const bool registered = registerCommand(
    {"grouping", "Grouping tree: build time and depth, select and local rebuild per frame", [](CommandLine& line) {
         auto o = std::make_shared<Options>();
         line.option("--objects", o->objects, "Number of objects").showDefault();
         line.option("--frames", o->frames, "Frames of the camera path and of motion").showDefault();
         line.option("--seed", o->seed, "Generator seed").showDefault();
         return [o] { return run(*o); };
     }});

}  // namespace
}  // namespace arcomp
