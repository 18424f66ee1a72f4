#include "graph/core/Bounds.hpp"
#include "graph/core/Frustum.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <random>
#include <vector>

using namespace arcomp;

TEST(Bounds, sphereAroundPointsHoldsEveryPoint) {
    const std::vector<glm::vec3> points{{0, 0, 0}, {2, 0, 0}, {0, 4, 0}, {1, 1, -3}};
    const Sphere s = sphereAround(points);
    for (const glm::vec3& p : points) EXPECT_LE(glm::length(p - s.center), s.radius + 1e-5f);
    EXPECT_NEAR(s.center.x, 1.0f, 1e-6f);
    EXPECT_NEAR(s.center.y, 2.0f, 1e-6f);
}

TEST(Bounds, mergedSphereEnclosesBothAndIsMinimalForDisjointSpheres) {
    const Sphere a{{0, 0, 0}, 1}, b{{10, 0, 0}, 2};
    const Sphere m = merged(a, b);
    EXPECT_TRUE(contains(m, a));
    EXPECT_TRUE(contains(m, b));
    EXPECT_NEAR(m.radius, 6.5f, 1e-5f);  // (10 + 1 + 2) / 2
    EXPECT_NEAR(m.center.x, 5.5f, 1e-5f);
}

TEST(Bounds, mergeWithEmptyIsIdentity) {
    const Sphere a{{1, 2, 3}, 4};
    EXPECT_EQ(merged(a, Sphere{}).radius, 4.0f);
    EXPECT_EQ(merged(Sphere{}, a).center, a.center);
    EXPECT_TRUE(merged(Sphere{}, Sphere{}).empty());
}

TEST(Bounds, transformedSphereScalesByLargestAxis) {
    const glm::mat4 m = glm::scale(glm::translate(glm::mat4(1), {5, 0, 0}), {1, 3, 2});
    const Sphere s = transformed(Sphere{{1, 0, 0}, 1}, m);
    EXPECT_NEAR(s.center.x, 6.0f, 1e-6f);
    EXPECT_NEAR(s.radius, 3.0f, 1e-6f);
}

TEST(Bounds, transformedBoxHoldsRotatedCorners) {
    const Box b{{-1, -1, -1}, {1, 1, 1}};
    const Box r = transformed(b, glm::rotate(glm::mat4(1), glm::radians(45.0f), {0, 1, 0}));
    EXPECT_NEAR(r.max.x, std::sqrt(2.0f), 1e-5f);
    EXPECT_NEAR(r.max.y, 1.0f, 1e-5f);
}

TEST(Frustum, classifiesSpheresInsideStraddlingAndOutside) {
    const glm::mat4 proj = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f);
    const glm::mat4 view = glm::lookAt(glm::vec3(0), {0, 0, -1}, {0, 1, 0});
    const Frustum f = Frustum::fromViewProjection(proj * view);
    EXPECT_EQ(f.classify({{0, 0, -10}, 1}), Containment::Inside);
    EXPECT_EQ(f.classify({{0, 0, 10}, 1}), Containment::Outside);       // behind the eye
    EXPECT_EQ(f.classify({{0, 0, -200}, 1}), Containment::Outside);     // beyond far
    EXPECT_EQ(f.classify({{0, 0, -100}, 1}), Containment::Intersects);  // on the far plane
    // At distance 10 the half-width is 10 * tan(30 deg) = 5.77.
    EXPECT_EQ(f.classify({{7.5f, 0, -10}, 1}), Containment::Outside);
    EXPECT_EQ(f.classify({{5.77f, 0, -10}, 1}), Containment::Intersects);
    EXPECT_EQ(f.classify(Sphere{}), Containment::Outside);
}

TEST(Frustum, runOfSpheresGetsTheAnswersOfOneAtATime) {
    const glm::mat4 proj = glm::perspective(glm::radians(60.0f), 16.0f / 9.0f, 0.1f, 100.0f);
    const glm::mat4 view = glm::lookAt(glm::vec3(1, 2, 3), {4, 0, -6}, {0, 1, 0});
    const Frustum f = Frustum::fromViewProjection(proj * view);
    std::mt19937 random(7);
    std::uniform_real_distribution<float> coordinate(-60.0f, 60.0f), radius(-2.0f, 20.0f);
    constexpr std::size_t kSpheres = 3 * Frustum::kMaxRun;
    std::vector<float> x(kSpheres), y(kSpheres), z(kSpheres), r(kSpheres);
    for (std::size_t i = 0; i < kSpheres; ++i) {
        x[i] = coordinate(random);
        y[i] = coordinate(random);
        z[i] = coordinate(random);
        r[i] = radius(random);  // some negative: empty spheres
    }
    int seen[3] = {0, 0, 0};
    for (std::uint32_t first = 0; first < Frustum::kMaxRun; ++first)
        for (std::uint32_t count = 1; count <= Frustum::kMaxRun; ++count) {
            const RunContainment run = f.classifyRun(&x[first], &y[first], &z[first], &r[first], count);
            for (std::uint32_t i = 0; i < count; ++i) {
                const Containment one = f.classify({{x[first + i], y[first + i], z[first + i]}, r[first + i]});
                ++seen[static_cast<int>(one)];
                EXPECT_EQ((run.outside >> i) & 1u, one == Containment::Outside ? 1u : 0u) << "sphere " << first + i;
                EXPECT_EQ((run.inside >> i) & 1u, one == Containment::Inside ? 1u : 0u) << "sphere " << first + i;
            }
            if (count < 32) {  // no bits past the run
                EXPECT_EQ(run.outside >> count, 0u);
                EXPECT_EQ(run.inside >> count, 0u);
            }
        }
    // The spheres cover all three answers, so each was compared.
    EXPECT_GT(seen[0], 0);
    EXPECT_GT(seen[1], 0);
    EXPECT_GT(seen[2], 0);
}
