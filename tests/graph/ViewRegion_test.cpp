#include "graph/silhouette/ViewRegion.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace arcomp;

TEST(ViewRegion, boxContainsItsInsideAndFacesButNotOutside) {
    const ViewRegion r = ViewRegion::fromBox({{0, 0, 0}, {1, 2, 3}});
    EXPECT_EQ(r.vertices().size(), 8u);
    EXPECT_EQ(r.planes().size(), 6u);
    EXPECT_TRUE(r.contains({0.5f, 1.0f, 1.5f}));
    EXPECT_TRUE(r.contains({1.0f, 2.0f, 3.0f}));
    EXPECT_FALSE(r.contains({1.01f, 1.0f, 1.5f}));
    EXPECT_FALSE(r.contains({0.5f, -0.01f, 1.5f}));
    EXPECT_FALSE(r.contains({0.5f, 1.0f, 3.01f}));
}

TEST(ViewRegion, hullOfTetrahedronHasFourPlanesAndTestsPoints) {
    const glm::vec3 p[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const ViewRegion r = ViewRegion::fromVertices(p);
    EXPECT_EQ(r.planes().size(), 4u);
    EXPECT_TRUE(r.contains({0.2f, 0.2f, 0.2f}));
    EXPECT_FALSE(r.contains({0.4f, 0.4f, 0.4f}));  // beyond x + y + z = 1
    EXPECT_FALSE(r.contains({-0.1f, 0.2f, 0.2f}));
}

TEST(ViewRegion, interiorPointsAreDroppedFromVertices) {
    const glm::vec3 p[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.1f, 0.1f, 0.1f}};
    const ViewRegion r = ViewRegion::fromVertices(p);
    EXPECT_EQ(r.vertices().size(), 4u);
}

TEST(ViewRegion, hullOfCubeCornersMatchesTheBox) {
    const ViewRegion box = ViewRegion::fromBox({{-1, -1, -1}, {1, 1, 1}});
    const ViewRegion hull = ViewRegion::fromVertices(box.vertices());
    EXPECT_EQ(hull.planes().size(), 6u);
    for (const glm::vec3 q : {glm::vec3(0.9f, -0.9f, 0.5f), glm::vec3(1.1f, 0, 0), glm::vec3(0, 0, -1.2f)})
        EXPECT_EQ(hull.contains(q), box.contains(q));
}

TEST(ViewRegion, flatOrTooFewPointsAreRefused) {
    const glm::vec3 flat[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    EXPECT_THROW(ViewRegion::fromVertices(flat), std::invalid_argument);
    const glm::vec3 three[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    EXPECT_THROW(ViewRegion::fromVertices(three), std::invalid_argument);
    EXPECT_THROW(ViewRegion::fromBox({{0, 0, 0}, {1, 0, 1}}), std::invalid_argument);
}
