#include "graph/core/Bounds.hpp"
#include "graph/core/Frustum.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

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
    EXPECT_EQ(f.classify({{0, 0, 10}, 1}), Containment::Outside);      // behind the eye
    EXPECT_EQ(f.classify({{0, 0, -200}, 1}), Containment::Outside);    // beyond far
    EXPECT_EQ(f.classify({{0, 0, -100}, 1}), Containment::Intersects); // on the far plane
    // At distance 10 the half-width is 10 * tan(30 deg) = 5.77.
    EXPECT_EQ(f.classify({{7.5f, 0, -10}, 1}), Containment::Outside);
    EXPECT_EQ(f.classify({{5.77f, 0, -10}, 1}), Containment::Intersects);
    EXPECT_EQ(f.classify(Sphere{}), Containment::Outside);
}
