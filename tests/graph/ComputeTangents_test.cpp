// computeTangents: the tangent frame a normal map is drawn in, glTF's way
// (bitangent = cross(normal, tangent) * w, pointing up the image, towards
// decreasing v).

#include "graph/core/Geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace arcomp;

namespace {

// A unit quad in the xy plane, normal +z, two counter-clockwise triangles.
const std::vector<glm::vec3> kQuad{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
const std::vector<glm::vec3> kUp(4, glm::vec3(0, 0, 1));
const std::vector<std::uint32_t> kTwoTriangles{0, 1, 2, 0, 2, 3};

void expectNear(const glm::vec4& got, const glm::vec4& want) {
    EXPECT_NEAR(got.x, want.x, 1e-5f);
    EXPECT_NEAR(got.y, want.y, 1e-5f);
    EXPECT_NEAR(got.z, want.z, 1e-5f);
    EXPECT_EQ(got.w, want.w);
}

}  // namespace

TEST(ComputeTangents, uAlongXWithVDownTheImageGivesTangentXAndPositiveSign) {
    // As glTF exporters write a quad: u = x, v = 1 - y (image rows top down).
    const std::vector<glm::vec2> uv{{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    const auto t = computeTangents(kQuad, kUp, uv, kTwoTriangles);
    ASSERT_EQ(t.size(), 4u);
    for (const glm::vec4& v : t) expectNear(v, {1, 0, 0, 1});
}

TEST(ComputeTangents, mirroredUFlipsTheSign) {
    const std::vector<glm::vec2> uv{{1, 1}, {0, 1}, {0, 0}, {1, 0}};
    for (const glm::vec4& v : computeTangents(kQuad, kUp, uv, kTwoTriangles)) expectNear(v, {-1, 0, 0, -1});
}

TEST(ComputeTangents, frameFollowsARotatedMapping) {
    // uv = R(a) (x, y): u grows along (cos a, -sin a), v along (sin a, cos a)
    // in the plane. The tangent is dP/du; v grows "up" the quad, against the
    // image's rows, so the bitangent cross(n, t) * w must point back down.
    const float a = 0.3f, c = std::cos(a), s = std::sin(a);
    std::vector<glm::vec2> uv;
    for (const glm::vec3& p : kQuad) uv.push_back({c * p.x - s * p.y, s * p.x + c * p.y});
    const auto t = computeTangents(kQuad, kUp, uv, kTwoTriangles);
    for (const glm::vec4& v : t) {
        expectNear(v, {c, -s, 0, -1});
        const glm::vec3 bitangent = glm::cross(glm::vec3(0, 0, 1), glm::vec3(v)) * v.w;
        EXPECT_NEAR(glm::dot(bitangent, glm::vec3(s, c, 0)), -1.0f, 1e-5f);
    }
}

TEST(ComputeTangents, tangentIsMadePerpendicularToASlantedNormal) {
    const glm::vec3 n = glm::normalize(glm::vec3(0.3f, 0.0f, 1.0f));
    const std::vector<glm::vec2> uv{{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    for (const glm::vec4& v : computeTangents(kQuad, std::vector<glm::vec3>(4, n), uv, kTwoTriangles)) {
        EXPECT_NEAR(glm::dot(glm::vec3(v), n), 0.0f, 1e-6f);
        EXPECT_NEAR(glm::length(glm::vec3(v)), 1.0f, 1e-6f);
        EXPECT_GT(v.x, 0.9f);  // still mostly along u
        EXPECT_EQ(v.w, 1.0f);
    }
}

TEST(ComputeTangents, degenerateUvsGiveAUnitTangentPerpendicularToTheNormalNeverNaN) {
    const std::vector<glm::vec3> normals{glm::normalize(glm::vec3(1, 2, 3)), {0, 0, 1}, {1, 0, 0}, {0, -1, 0}};
    for (const std::vector<glm::vec2>& uv : {std::vector<glm::vec2>(4, glm::vec2(0.5f)),                 // one point
                                             std::vector<glm::vec2>{{0, 0}, {1, 0}, {2, 0}, {3, 0}}}) {  // one line
        const auto t = computeTangents(kQuad, normals, uv, kTwoTriangles);
        ASSERT_EQ(t.size(), 4u);
        for (std::size_t i = 0; i < t.size(); ++i) {
            EXPECT_TRUE(std::isfinite(t[i].x) && std::isfinite(t[i].y) && std::isfinite(t[i].z)) << i;
            EXPECT_NEAR(glm::length(glm::vec3(t[i])), 1.0f, 1e-5f) << i;
            EXPECT_NEAR(glm::dot(glm::vec3(t[i]), normals[i]), 0.0f, 1e-5f) << i;
            EXPECT_TRUE(t[i].w == 1.0f || t[i].w == -1.0f) << i;
        }
    }
}

TEST(ComputeTangents, aVertexNoTriangleUsesStillGetsAFrame) {
    std::vector<glm::vec3> positions = kQuad;
    positions.push_back({5, 5, 5});
    std::vector<glm::vec3> normals = kUp;
    normals.push_back({0, 1, 0});
    const std::vector<glm::vec2> uv{{0, 1}, {1, 1}, {1, 0}, {0, 0}, {0, 0}};
    const auto t = computeTangents(positions, normals, uv, kTwoTriangles);
    ASSERT_EQ(t.size(), 5u);
    EXPECT_NEAR(glm::length(glm::vec3(t[4])), 1.0f, 1e-5f);
    EXPECT_NEAR(t[4].y, 0.0f, 1e-5f);
}
