#include "graph/points/LdiRenderer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

using namespace arcomp;

namespace {

// An LDI holding exactly `ids`, each in the pixel the camera projects it to.
Ldi ldiHolding(const LdiCamera& cam, const PointCloud& cloud, const std::vector<std::uint32_t>& ids) {
    Ldi ldi;
    ldi.camera = cam;
    const std::size_t pixels = static_cast<std::size_t>(cam.width * cam.height);
    std::vector<std::vector<std::pair<float, std::uint32_t>>> lists(pixels);
    for (std::uint32_t id : ids) {
        const LdiPlacement p = placeInLdi(cam, cloud.positions[id]);
        lists[p.pixel].emplace_back(glm::distance(cloud.positions[id], cam.eye), id);
    }
    ldi.pixelStart.push_back(0);
    for (auto& list : lists) {
        std::sort(list.begin(), list.end());
        for (auto& [d, id] : list) {
            ldi.points.push_back(id);
            ldi.rayDepth.push_back(d);
        }
        ldi.pixelStart.push_back(static_cast<std::uint32_t>(ldi.points.size()));
    }
    return ldi;
}

// Three half-transparent points on the view axis: red far, green middle,
// blue near; `owner` says which of two LDIs holds each.
LdiSet threeOnTheAxis(std::array<std::uint8_t, 3> owner) {
    LdiSet set;
    set.cloud.positions = {{0, 0, -3}, {0, 0, 0}, {0, 0, 3}};
    set.cloud.colors = {{1, 0, 0, 0.5f}, {0, 1, 0, 0.5f}, {0, 0, 1, 0.5f}};
    set.cloud.pointSize = 0.01f;
    const std::vector<LdiCamera> cams = {LdiCamera::lookAt({10, 0, 0}, {0, 0, 0}, {0, 1, 0}, 60.0f, 16, 16),
                                         LdiCamera::lookAt({-10, 1, 0}, {0, 0, 0}, {0, 1, 0}, 60.0f, 16, 16)};
    set.pointLdi.assign(owner.begin(), owner.end());
    for (std::uint8_t l = 0; l < 2; ++l) {
        std::vector<std::uint32_t> ids;
        for (std::uint32_t i = 0; i < 3; ++i)
            if (owner[i] == l) ids.push_back(i);
        set.ldis.push_back(ldiHolding(cams[l], set.cloud, ids));
    }
    return set;
}

const View kEye = View::lookAt({0, 0, 10}, {0, 0, 0}, {0, 1, 0}, 30.0f, {9, 9}, 0.1f, 100.0f);

glm::u8vec4 pixel(const PointImage& img, int x, int y) {
    const std::uint8_t* p = &img.rgba[static_cast<std::size_t>(y * img.width + x) * 4];
    return {p[0], p[1], p[2], p[3]};
}

}  // namespace

TEST(LdiRenderer, mergeCompositesAllLdisFarthestFirst) {
    // Over, back to front, premultiplied: R = .5*.5*.5, G = .5*.5, B = .5, A = 1 - .5^3.
    const glm::u8vec4 expected(32, 64, 128, 223);
    for (const auto owner : {std::array<std::uint8_t, 3>{0, 1, 0}, std::array<std::uint8_t, 3>{1, 0, 1},
                             std::array<std::uint8_t, 3>{0, 0, 1}, std::array<std::uint8_t, 3>{1, 1, 1}}) {
        const LdiSet set = threeOnTheAxis(owner);
        LdiRenderer renderer(set, 2);
        const PointImage& img = renderer.render(kEye);
        ASSERT_EQ(img.width, 9);
        EXPECT_EQ(pixel(img, 4, 4), expected) << "owners " << int(owner[0]) << int(owner[1]) << int(owner[2]);
        EXPECT_NEAR(img.depth[4 * 9 + 4], 7.0f, 1e-4f) << "the nearest point's view depth";
        EXPECT_TRUE(std::isinf(img.depth[0])) << "no point reaches the corner";
        EXPECT_EQ(pixel(img, 0, 0), glm::u8vec4(0));
    }
}

TEST(LdiRenderer, depthSortedReferenceMatchesTheHandComposite) {
    const LdiSet set = threeOnTheAxis({0, 1, 0});
    LdiRenderer renderer(set, 1);
    EXPECT_EQ(pixel(renderer.renderDepthSorted(kEye), 4, 4), glm::u8vec4(32, 64, 128, 223));
    // From the other side the order reverses: red is nearest.
    const View behind = View::lookAt({0, 0, -10}, {0, 0, 0}, {0, 1, 0}, 30.0f, {9, 9}, 0.1f, 100.0f);
    EXPECT_EQ(pixel(renderer.renderDepthSorted(behind), 4, 4), glm::u8vec4(128, 64, 32, 223));
    EXPECT_EQ(pixel(renderer.render(behind), 4, 4), glm::u8vec4(128, 64, 32, 223));
}

TEST(LdiRenderer, splatFootprintGrowsWithTheProjectedPointSize) {
    LdiSet set = threeOnTheAxis({0, 0, 0});
    LdiRenderer renderer(set, 2);
    const std::size_t small = renderer.render(kEye).coveredPixels();
    set.cloud.pointSize = 1.0f;  // a unit point at distance 7..13 spans about two of these pixels
    const std::size_t large = renderer.render(kEye).coveredPixels();
    EXPECT_EQ(small, 1u);
    EXPECT_GT(large, 4u);
}

TEST(LdiRenderer, singleLdiCompositesItsMcMillanStreamDirectly) {
    LdiSet set = threeOnTheAxis({0, 0, 0});
    set.ldis.pop_back();  // one LDI: no projection buffers, no merge
    for (int threads : {1, 2}) {
        LdiRenderer renderer(set, threads);
        const PointImage& img = renderer.render(kEye);
        EXPECT_EQ(pixel(img, 4, 4), glm::u8vec4(32, 64, 128, 223)) << threads << " threads";
        EXPECT_NEAR(img.depth[4 * 9 + 4], 7.0f, 1e-4f);
        EXPECT_EQ(renderer.lastSplatCount(), 3u);
    }
}

TEST(LdiRenderer, pixelsNoLongerReachedAreClearedInTheNextFrame) {
    for (const auto owner : {std::array<std::uint8_t, 3>{0, 0, 0}, std::array<std::uint8_t, 3>{0, 1, 0}}) {
        const LdiSet set = threeOnTheAxis(owner);
        for (int threads : {1, 2}) {
            LdiRenderer renderer(set, threads);
            ASSERT_EQ(pixel(renderer.render(kEye), 4, 4).a, 223);
            // Looking lower moves the points up to the first rows.
            const View lower = View::lookAt({0, -2, 10}, {0, -2, 0}, {0, 1, 0}, 30.0f, {9, 9}, 0.1f, 100.0f);
            const PointImage& img = renderer.render(lower);
            EXPECT_EQ(pixel(img, 4, 4), glm::u8vec4(0)) << threads << " threads, owners " << int(owner[1]);
            EXPECT_TRUE(std::isinf(img.depth[4 * 9 + 4]));
            std::size_t top = 0;
            for (int y = 0; y < 3; ++y)
                for (int x = 0; x < 9; ++x) top += pixel(img, x, y).a != 0;
            EXPECT_GT(top, 0u);
            EXPECT_EQ(img.coveredPixels(), top) << "nothing left below the first rows";
        }
    }
}

TEST(LdiRenderer, singleStreamMatchesTheProjectionBuffersPixelForPixel) {
    // The single stream composites four pixels of a row at once from colour
    // planes; the projection buffers take each splat alone. The same points
    // in one LDI, and in the first of two LDIs (the second empty), must give
    // the same image: at the right edge of a width that is no multiple of
    // four, and across the rows where two threads' bands meet.
    PointCloud cloud;
    cloud.pointSize = 0.35f;
    std::uint32_t seed = 7;
    const auto unit = [&] { return static_cast<float>((seed = seed * 1664525u + 1013904223u) >> 8) / 16777216.0f; };
    // Some beyond every edge of the view.
    for (int i = 0; i < 800; ++i) {
        cloud.positions.push_back({unit() * 10.0f - 5.0f, unit() * 6.0f - 3.0f, unit() * 2.0f - 1.0f});
        cloud.colors.push_back({unit(), unit(), unit(), 0.2f + 0.7f * unit()});
    }
    std::vector<std::uint32_t> all(cloud.positions.size());
    std::iota(all.begin(), all.end(), 0u);
    const LdiCamera front = LdiCamera::lookAt({0, 0, 12}, {0, 0, 0}, {0, 1, 0}, 40.0f, 32, 32);
    const LdiCamera back = LdiCamera::lookAt({0, 0, -12}, {0, 0, 0}, {0, 1, 0}, 40.0f, 32, 32);
    LdiSet one, two;
    one.cloud = two.cloud = cloud;
    one.pointLdi.assign(all.size(), 0);
    two.pointLdi = one.pointLdi;
    one.ldis = {ldiHolding(front, cloud, all)};
    two.ldis = {ldiHolding(front, cloud, all), ldiHolding(back, cloud, {})};
    const View eye = View::lookAt({1.5f, 0.8f, 9.0f}, {0, 0, 0}, {0, 1, 0}, 30.0f, {37, 23}, 0.1f, 100.0f);
    LdiRenderer single(one, 2), merged(two, 2);
    const PointImage& a = single.render(eye);
    const PointImage& b = merged.render(eye);
    ASSERT_EQ(single.lastSplatCount(), merged.lastSplatCount());
    ASSERT_GT(a.coveredPixels(), 37u * 23u / 2u) << "the points must cover most of the image";
    std::size_t rightEdge = 0;
    for (int y = 0; y < 23; ++y)
        for (int x = 0; x < 37; ++x) {
            const glm::ivec4 d = glm::abs(glm::ivec4(pixel(a, x, y)) - glm::ivec4(pixel(b, x, y)));
            EXPECT_LE(std::max({d.x, d.y, d.z, d.w}), 1) << "pixel " << x << "," << y;
            EXPECT_EQ(a.depth[static_cast<std::size_t>(y * 37 + x)], b.depth[static_cast<std::size_t>(y * 37 + x)]);
            rightEdge += x == 36 && pixel(a, x, y).a != 0;
        }
    EXPECT_GT(rightEdge, 0u) << "some points must reach the last column";
}

TEST(LdiRenderer, anEnormousPointCoversTheImageOnBothPaths) {
    // A footprint far wider than int can count (the point size of a broken
    // voxel file, say) is clipped to the image before it becomes pixels.
    for (const auto owner : {std::array<std::uint8_t, 3>{0, 0, 0}, std::array<std::uint8_t, 3>{0, 1, 0}}) {
        LdiSet set = threeOnTheAxis(owner);
        if (owner[1] == 0) set.ldis.pop_back();  // one LDI: the single stream
        for (float size : {1e12f, 1e30f}) {
            set.cloud.pointSize = size;
            LdiRenderer renderer(set, 2);
            const PointImage& img = renderer.render(kEye);
            EXPECT_EQ(img.coveredPixels(), 81u) << size;
            EXPECT_EQ(renderer.lastSplatCount(), 3u * 81u) << size;
            EXPECT_EQ(pixel(img, 0, 8), glm::u8vec4(32, 64, 128, 223)) << size << ", owners " << int(owner[1]);
        }
    }
}
