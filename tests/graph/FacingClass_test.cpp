#include "graph/core/Geometry.hpp"
#include "graph/silhouette/FacingClass.hpp"
#include "graph/silhouette/ViewRegion.hpp"

#include <gtest/gtest.h>

using namespace arcomp;

namespace {

// makeBox's faces in order +X, -X, +Y, -Y, +Z, -Z, two triangles each.
enum Face { PX, NX, PY, NY, PZ, NZ };

Facing faceOf(const std::vector<Facing>& f, Face face) {
    EXPECT_EQ(f[2 * face], f[2 * face + 1]);
    return f[2 * face];
}

std::vector<Facing> classifyCube(const Box& region) {
    const Geometry cube = makeBox({2, 2, 2});  // faces on the planes x, y, z = +-1
    return classifyTriangles(cube.positions, cube.indices, ViewRegion::fromBox(region).vertices());
}

}  // namespace

TEST(FacingClass, cubeFaceIsFrontMeshFromRegionInFrontOfIt) {
    const auto f = classifyCube({{-0.5f, -0.5f, 3}, {0.5f, 0.5f, 4}});
    EXPECT_EQ(faceOf(f, PZ), Facing::Front);
    EXPECT_EQ(faceOf(f, NZ), Facing::Back);
    EXPECT_EQ(faceOf(f, PX), Facing::Back);  // the eye is behind the plane x = 1
    EXPECT_EQ(faceOf(f, NY), Facing::Back);
}

TEST(FacingClass, cubeFaceIsBackMeshFromRegionBehindIt) {
    const auto f = classifyCube({{-0.5f, -0.5f, -4}, {0.5f, 0.5f, -3}});
    EXPECT_EQ(faceOf(f, PZ), Facing::Back);
    EXPECT_EQ(faceOf(f, NZ), Facing::Front);
}

TEST(FacingClass, cubeFaceIsSilhouetteMeshFromRegionStraddlingItsPlane) {
    const auto f = classifyCube({{2, -0.5f, 0.5f}, {3, 0.5f, 1.5f}});  // z from 0.5 to 1.5 crosses z = 1
    EXPECT_EQ(faceOf(f, PZ), Facing::Silhouette);
    EXPECT_EQ(faceOf(f, PX), Facing::Front);
    EXPECT_EQ(faceOf(f, NX), Facing::Back);
}

TEST(FacingClass, regionTouchingFacePlaneCountsAsSilhouette) {
    const auto f = classifyCube({{2, -0.5f, 1}, {3, 0.5f, 2}});  // bottom face lies on z = 1
    EXPECT_EQ(faceOf(f, PZ), Facing::Silhouette);
}

TEST(FacingClass, tetrahedronAgainstRegionsInFrontBehindAndStraddling) {
    const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    // Outward-facing: the slanted face x + y + z = 1, then the faces on x, y, z = 0.
    const std::vector<std::uint32_t> idx = {1, 2, 3, 0, 3, 2, 0, 1, 3, 0, 2, 1};
    auto classify = [&](const Box& b) { return classifyTriangles(p, idx, ViewRegion::fromBox(b).vertices()); };

    const auto front = classify({{2, 2, 2}, {3, 3, 3}});
    EXPECT_EQ(front[0], Facing::Front);
    EXPECT_EQ(front[1], Facing::Back);
    EXPECT_EQ(front[2], Facing::Back);
    EXPECT_EQ(front[3], Facing::Back);

    const auto behind = classify({{-3, -3, -3}, {-2, -2, -2}});
    EXPECT_EQ(behind[0], Facing::Back);
    EXPECT_EQ(behind[1], Facing::Front);
    EXPECT_EQ(behind[2], Facing::Front);
    EXPECT_EQ(behind[3], Facing::Front);

    // x + y + z runs from 0 to 2.5 over this box: both sides of the slanted plane.
    const auto straddling = classify({{2, 2, -4}, {3, 3, -3.5f}});
    EXPECT_EQ(straddling[0], Facing::Silhouette);
    EXPECT_EQ(straddling[3], Facing::Front);  // z < 0 everywhere: in front of the face on z = 0
}

TEST(FacingClass, singleEyeOnPlaneIsNeitherFrontNorBack) {
    const glm::vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    EXPECT_TRUE(frontFacingFrom(a, b, c, {0.3f, 0.3f, 1}));
    EXPECT_TRUE(backFacingFrom(a, b, c, {0.3f, 0.3f, -1}));
    EXPECT_FALSE(frontFacingFrom(a, b, c, {5, 5, 0}));
    EXPECT_FALSE(backFacingFrom(a, b, c, {5, 5, 0}));
}
