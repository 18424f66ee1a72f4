#include "graph/core/SelectPass.hpp"
#include "graph/core/View.hpp"
#include "graph/silhouette/CoverageRaster.hpp"
#include "graph/silhouette/FlatMesh.hpp"
#include "graph/silhouette/SilhouetteMesh.hpp"
#include "graph/silhouette/SilhouetteNodes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>

using namespace arcomp;

namespace {

// Eyes to test a region from: its vertices, its centre and random points in it.
std::vector<glm::vec3> eyesIn(const ViewRegion& region, int randomCount) {
    std::vector<glm::vec3> eyes(region.vertices().begin(), region.vertices().end());
    const Box b = region.box();
    eyes.push_back(b.center());
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int i = 0; i < randomCount; ++i) eyes.push_back(b.min + glm::vec3(u(rng), u(rng), u(rng)) * b.size());
    return eyes;
}

MaskDifference worstDifference(const SilhouetteMesh& m, std::size_t region, const std::vector<glm::vec3>& eyes,
                               const glm::vec3& target, float radius) {
    MaskDifference worst;
    for (const glm::vec3& eye : eyes) {
        const float d = glm::length(eye - target);
        const View v = View::lookAt(eye, target, {0, 1, 0}, glm::degrees(2.0f * std::atan(1.2f * radius / d)),
                                    {256, 256}, 0.01f, 100.0f);
        CoverageMask full(256, 256), reduced(256, 256);
        EXPECT_EQ(rasterizeCoverage(m.positions, m.indicesOf(m.full), v.viewProjection(), full), 0u);
        EXPECT_EQ(rasterizeCoverage(m.positions, m.indicesOf(m.ranges[region]), v.viewProjection(), reduced), 0u);
        EXPECT_GT(full.covered(), 1000u);
        const MaskDifference diff = compareMasks(full, reduced);
        worst.differing = std::max(worst.differing, diff.differing);
        worst.differingFarFromOutline = std::max(worst.differingFarFromOutline, diff.differingFarFromOutline);
    }
    return worst;
}

// makeUvSphere's seam and pole vertices differ in the last bits; rounding
// lets the bake weld them into a closed surface.
Geometry closedSphere(int slices, int stacks) {
    Geometry g = makeUvSphere(1.0f, slices, stacks);
    for (glm::vec3& p : g.positions) p = glm::round(p * 1e5f) / 1e5f;
    return g;
}

// A closed sphere with bumps and dents: concave enough that unchecked
// simplification of FM folds triangles over the outline.
Geometry bumpySphere() {
    Geometry g = closedSphere(96, 48);
    for (glm::vec3& p : g.positions)
        p *= 1.0f +
             0.15f * std::sin(7.0f * std::atan2(p.z, p.x)) * std::sin(6.0f * std::acos(std::clamp(p.y, -1.0f, 1.0f)));
    return g;
}

}  // namespace

TEST(SilhouetteMesh, regionsIndexOneSharedVertexBuffer) {
    const Geometry sphere = makeUvSphere(1.0f, 32, 16);
    std::vector<ViewRegion> regions = regionsAround({{0, 0, 0}, 1.0f}, 4);
    const SilhouetteMesh m = bakeSilhouetteMesh(sphere.positions, sphere.indices, regions);
    ASSERT_EQ(m.ranges.size(), 4u);
    EXPECT_EQ(m.full.firstIndex, 0u);
    std::uint32_t next = m.full.indexCount;
    for (const SilhouetteRange& r : m.ranges) {
        EXPECT_EQ(r.firstIndex, next);  // lists follow each other in the one index buffer
        EXPECT_GT(r.indexCount, 0u);
        EXPECT_LT(r.indexCount, m.full.indexCount);
        next += r.indexCount;
    }
    EXPECT_EQ(next, m.indices.size());
    for (std::uint32_t i : m.indices) ASSERT_LT(i, m.positions.size());
    // Welding the UV sphere's seam leaves fewer vertices than it came with, all shared.
    EXPECT_LT(m.positions.size(), sphere.positions.size());
}

TEST(SilhouetteMesh, eyePicksItsRegionAndFallsBackToFullMesh) {
    const Geometry sphere = makeUvSphere(1.0f, 16, 8);
    std::vector<ViewRegion> regions = {ViewRegion::fromBox({{-0.5f, -0.5f, 3}, {0.5f, 0.5f, 4}}),
                                       ViewRegion::fromBox({{-0.5f, -0.5f, -4}, {0.5f, 0.5f, -3}})};
    const SilhouetteMesh m = bakeSilhouetteMesh(sphere.positions, sphere.indices, regions);
    EXPECT_EQ(m.regionAt({0, 0, 3.5f}), 0);
    EXPECT_EQ(m.regionAt({0, 0, -3.5f}), 1);
    EXPECT_EQ(m.rangeFor({0, 0, -3.5f}).firstIndex, m.ranges[1].firstIndex);
    EXPECT_EQ(m.rangeFor({0, 5, 0}).indexCount, m.full.indexCount);
}

TEST(SilhouetteMesh, maskUnchangedFromEveryRegionVertex) {
    const Geometry sphere = bumpySphere();
    std::vector<ViewRegion> regions = regionsAround({{0, 0, 0}, 1.0f}, 3);
    std::vector<SilhouetteRegionReport> report;
    const SilhouetteMesh m = bakeSilhouetteMesh(sphere.positions, sphere.indices, regions, &report);
    for (std::size_t r = 0; r < m.regions.size(); ++r) {
        EXPECT_LT(report[r].frontAfter, report[r].front) << "region " << r << ": FM was not simplified at all";
        EXPECT_EQ(report[r].backKept, 0u);  // closed mesh: BM adds nothing
        const MaskDifference d = worstDifference(m, r, eyesIn(m.regions[r], 20), {0, 0, 0}, 1.2f);
        EXPECT_EQ(d.differingFarFromOutline, 0u) << "region " << r;
    }
}

// The bunny folds where a sphere does not: without the front-facing and
// border checks its reduced masks differ far from the outline.
TEST(SilhouetteMesh, bunnyMaskUnchangedFromRegionVerticesAndInside) {
    const std::filesystem::path file = std::filesystem::path(ARCOMP_SHARED_DATA) / "meshes/bunny.obj";
    if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not found";
    const FlatMesh bunny = flattenModel(parseObj(file));
    const Sphere bound = sphereAround(bunny.positions);
    std::vector<ViewRegion> regions = regionsAround(bound, 8);
    regions.resize(3);
    const SilhouetteMesh m = bakeSilhouetteMesh(bunny.positions, bunny.indices, regions);
    for (std::size_t r = 0; r < m.regions.size(); ++r) {
        EXPECT_LT(m.ranges[r].indexCount, m.full.indexCount / 2) << "region " << r;
        const MaskDifference d = worstDifference(m, r, eyesIn(m.regions[r], 8), bound.center, bound.radius);
        EXPECT_EQ(d.differingFarFromOutline, 0u) << "region " << r;
    }
}

TEST(SilhouetteMesh, backFacesSeenThroughAHoleAreKept) {
    // A box open at the top, seen from above: its floor faces away from every
    // eye, yet is what fills the opening.
    Geometry box = makeBox({2, 2, 2});
    std::vector<std::uint32_t> open;
    for (std::size_t t = 0; t < box.indices.size(); t += 3)
        if (t / 6 != 2) open.insert(open.end(), &box.indices[t], &box.indices[t] + 3);  // face 2 is +Y
    const ViewRegion above = ViewRegion::fromBox({{-0.3f, 4, -0.3f}, {0.3f, 5, 0.3f}});
    const MeshHoles holes = findHoles(box.positions, open);
    // makeBox does not share vertices between faces: bake welds them first.
    std::vector<SilhouetteRegionReport> report;
    const SilhouetteMesh m = bakeSilhouetteMesh(box.positions, open, {above}, &report);
    EXPECT_GT(holes.borderEdges, 0u);
    EXPECT_GT(report[0].backKept, 0u);
    const MaskDifference d = worstDifference(m, 0, eyesIn(m.regions[0], 10), {0, 0, 0}, 1.8f);
    EXPECT_EQ(d.differing, 0u);
}

TEST(SilhouetteReduction, checksRejectFlippedTrianglesAndMovedBorders) {
    const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    const std::vector<glm::vec3> eyes = {{0.5f, 0.5f, 2}, {3, 3, 1}};
    const std::vector<std::uint32_t> quad = {0, 1, 3, 0, 3, 2}, flipped = {0, 3, 1, 0, 3, 2};
    EXPECT_TRUE(allFrontFacing(p, quad, eyes));
    EXPECT_FALSE(allFrontFacing(p, flipped, eyes));
    const std::vector<std::uint32_t> otherDiagonal = {0, 1, 2, 1, 3, 2}, half = {0, 1, 3};
    EXPECT_EQ(borderChain(quad), borderChain(otherDiagonal));  // same outline, different inside
    EXPECT_NE(borderChain(quad), borderChain(half));
}

TEST(SilhouetteNodes, selectPassDrawsTheRangeOfTheRegionHoldingTheEye) {
    const Geometry sphere = makeUvSphere(1.0f, 16, 8);
    const SilhouetteMesh m = bakeSilhouetteMesh(sphere.positions, sphere.indices,
                                                {ViewRegion::fromBox({{-0.5f, -0.5f, 3}, {0.5f, 0.5f, 4}})});
    World world;
    Scene& scene = world.scene;
    SilhouetteNodes& table = world.silhouettes;
    // The node sits 10 units along x: regions are in its local space.
    const NodeId t = scene.addTransform(scene.root(), glm::mat4{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 10, 0, 0, 1});
    const NodeId n = addSilhouetteNode(scene, t, table, m, scene.addMaterial({}));
    scene.update();
    DrawList list;
    select(world, View::lookAt({10, 0, 3.5f}, {10, 0, 0}, {0, 1, 0}, 60.0f, {64, 64}), {}, list);
    ASSERT_EQ(list.items.size(), 1u);
    EXPECT_EQ(list.items[0].node, n);
    EXPECT_EQ(list.items[0].firstIndex, m.ranges[0].firstIndex);
    EXPECT_EQ(list.items[0].indexCount, m.ranges[0].indexCount);
    select(world, View::lookAt({10, 0, 8}, {10, 0, 0}, {0, 1, 0}, 60.0f, {64, 64}), {}, list);
    ASSERT_EQ(list.items.size(), 1u);
    EXPECT_EQ(list.items[0].firstIndex, m.full.firstIndex);
    EXPECT_EQ(list.items[0].indexCount, m.full.indexCount);
}
