#include "graph/points/McMillanOrder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

using namespace arcomp;

namespace {

constexpr int kSize = 16;

LdiCamera referenceCamera() {
    return LdiCamera::lookAt({0.0f, 0.0f, -10.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 60.0f, kSize, kSize);
}

glm::vec3 pixelCenterRay(const LdiCamera& c, int x, int y) { return c.rayDirection(x, y); }

// The new eye whose epipole falls on screen position `p`, at depth `z`
// in the LDI camera (positive: in front of the LDI's eye).
glm::vec3 eyeFor(const LdiCamera& c, glm::vec2 p, float z) {
    const glm::vec2 xy = (p - c.principal()) / c.focal * z;
    return c.eye + glm::transpose(c.rotation) * glm::vec3(xy, z);
}

// Closest points of the lines a + s*da and b + t*db: (s, t).
glm::dvec2 closestParameters(glm::dvec3 a, glm::dvec3 da, glm::dvec3 b, glm::dvec3 db) {
    const glm::dvec3 w = a - b;
    const double aa = glm::dot(da, da), ab = glm::dot(da, db), bb = glm::dot(db, db);
    const double d = glm::dot(da, w), e = glm::dot(db, w);
    const double den = aa * bb - ab * ab;
    return {(ab * e - bb * d) / den, (aa * e - ab * d) / den};
}

struct OccludingPair {
    std::uint32_t far, near;  // as seen from the new eye, on one line through it
};

// Points on the LDI's pixel-centre rays, with pairs built exactly collinear
// with the new eye: a point Q on one ray, and where the line from the eye
// through Q crosses another ray on the same epipolar line (the line through
// the epipole and Q's pixel, which passes through pixel centres because the
// epipole sits on the pixel-centre lattice).
struct Scenario {
    PointCloud cloud;
    std::vector<OccludingPair> pairs;
};

Scenario buildScenario(const LdiCamera& cam, glm::vec2 epipole, glm::vec3 eye, unsigned seed) {
    Scenario s;
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> pixel(0, kSize - 1);
    std::uniform_real_distribution<float> depth(6.0f, 14.0f);
    auto add = [&](glm::vec3 p) {
        s.cloud.positions.push_back(p);
        s.cloud.colors.emplace_back(1.0f);
        return static_cast<std::uint32_t>(s.cloud.size() - 1);
    };
    // Filler: several points per pixel so that each pixel's list matters.
    for (int i = 0; i < 600; ++i) {
        const int x = pixel(rng), y = pixel(rng);
        add(cam.eye + pixelCenterRay(cam, x, y) * depth(rng));
    }
    for (int attempt = 0; attempt < 4000 && s.pairs.size() < 300; ++attempt) {
        const glm::ivec2 a(pixel(rng), pixel(rng));
        // Step along the lattice line from the epipole through pixel a.
        const glm::vec2 toA = glm::vec2(a) + 0.5f - epipole;
        const glm::ivec2 step = glm::ivec2(glm::round(toA));
        const int g = std::gcd(std::abs(step.x), std::abs(step.y));
        if (g == 0) continue;
        const glm::ivec2 unit = step / g;
        const int k = std::uniform_int_distribution<int>(-3, 3)(rng);
        const glm::ivec2 b = a + unit * k;
        if (k == 0 || b.x < 0 || b.y < 0 || b.x >= kSize || b.y >= kSize) continue;
        const glm::vec3 q = cam.eye + pixelCenterRay(cam, a.x, a.y) * depth(rng);
        const glm::vec3 rayB = pixelCenterRay(cam, b.x, b.y);
        // Nearly parallel lines meet too far away to place the point reliably.
        if (glm::length(glm::cross(rayB, glm::normalize(q - eye))) < 0.05f) continue;
        const glm::dvec2 st = closestParameters(cam.eye, rayB, eye, q - eye);
        const double alongB = st.x, alongLine = st.y;
        if (alongB < 2.0 || alongB > 30.0 || alongLine < 0.05 || std::abs(alongLine - 1.0) < 0.05) continue;
        const glm::vec3 p = cam.eye + rayB * static_cast<float>(alongB);
        EXPECT_LT(glm::length(glm::dvec3(p) - (glm::dvec3(eye) + glm::dvec3(q - eye) * alongLine)), 1e-3)
            << "construction: lines must meet";
        const std::uint32_t qi = add(q), pi = add(p);
        // alongLine < 1: p lies between the eye and q, so it hides q.
        s.pairs.push_back(alongLine < 1.0f ? OccludingPair{qi, pi} : OccludingPair{pi, qi});
    }
    return s;
}

void expectBackToFront(glm::vec2 epipole, float eyeDepth, EpipoleSide column, EpipoleSide row) {
    const LdiCamera cam = referenceCamera();
    const glm::vec3 eye = eyeFor(cam, epipole, eyeDepth);
    const Epipole e = epipoleOf(cam, eye);
    EXPECT_EQ(e.column, column);
    EXPECT_EQ(e.row, row);
    EXPECT_EQ(e.inFront, eyeDepth > 0.0f);
    EXPECT_NEAR(e.pixel.x, epipole.x, 1e-3f);
    EXPECT_NEAR(e.pixel.y, epipole.y, 1e-3f);

    Scenario s = buildScenario(cam, epipole, eye, 7u + static_cast<unsigned>(epipole.x * 3 + epipole.y * 5 + eyeDepth));
    ASSERT_GT(s.pairs.size(), 20u) << "the scenario must hold occluding pairs to check";
    const LdiSet set = buildLdis(s.cloud, {cam});
    ASSERT_EQ(set.unregistered, 0u);
    std::vector<std::uint32_t> order;
    appendBackToFront(set.ldis[0], eye, order);
    ASSERT_EQ(order.size(), s.cloud.size()) << "every point is drawn exactly once";
    std::vector<std::size_t> rank(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) rank[order[i]] = i;

    // Across pixels: McMillan's guarantee for points hiding one another.
    int wrong = 0;
    for (const OccludingPair& p : s.pairs) wrong += rank[p.far] > rank[p.near];
    EXPECT_EQ(wrong, 0) << "of " << s.pairs.size() << " exactly occluding pairs";

    // Within each pixel: the walk equals sorting by distance from the eye.
    const Ldi& ldi = set.ldis[0];
    for (std::size_t px = 0; px + 1 < ldi.pixelStart.size(); ++px) {
        std::vector<std::uint32_t> drawn(ldi.points.begin() + ldi.pixelStart[px],
                                         ldi.points.begin() + ldi.pixelStart[px + 1]);
        std::sort(drawn.begin(), drawn.end(), [&](auto a, auto b) { return rank[a] < rank[b]; });
        std::vector<std::uint32_t> sorted = drawn;
        std::stable_sort(sorted.begin(), sorted.end(), [&](auto a, auto b) {
            return glm::distance(s.cloud.positions[a], eye) > glm::distance(s.cloud.positions[b], eye);
        });
        ASSERT_EQ(drawn, sorted) << "pixel " << px;
    }

    // Cut into pieces for several threads, the walk gives the same order.
    std::vector<std::uint32_t> whole(ldi.points.size());
    writeSlotsBackToFront(ldi, eye, 5, whole);
    for (std::size_t i = 0; i < whole.size(); ++i) ASSERT_EQ(ldi.points[whole[i] - 5], order[i]) << "slot " << i;
    for (std::size_t parts : {2u, 3u, 7u}) {
        std::vector<std::uint32_t> pieces(whole.size(), UINT32_MAX);
        for (std::size_t part = 0; part < parts; ++part) writeSlotsBackToFront(ldi, eye, 5, pieces, part, parts);
        EXPECT_EQ(pieces, whole) << parts << " pieces";
    }
}

// Epipole positions on the pixel-centre lattice: before, on and after the screen.
constexpr float kBefore = -6.5f, kInside = 7.5f, kAfter = 22.5f;
constexpr float kInFront = 30.0f;  // beyond the points, looking back at them
constexpr float kAmong = 9.0f;     // in front, among the points
constexpr float kBehind = -8.0f;

struct Case {
    float x, y;
    EpipoleSide column, row;
};
constexpr Case kCases[9] = {
    {kBefore, kBefore, EpipoleSide::Before, EpipoleSide::Before},
    {kInside, kBefore, EpipoleSide::Inside, EpipoleSide::Before},
    {kAfter, kBefore, EpipoleSide::After, EpipoleSide::Before},
    {kBefore, kInside, EpipoleSide::Before, EpipoleSide::Inside},
    {kInside, kInside, EpipoleSide::Inside, EpipoleSide::Inside},
    {kAfter, kInside, EpipoleSide::After, EpipoleSide::Inside},
    {kBefore, kAfter, EpipoleSide::Before, EpipoleSide::After},
    {kInside, kAfter, EpipoleSide::Inside, EpipoleSide::After},
    {kAfter, kAfter, EpipoleSide::After, EpipoleSide::After},
};

class McMillanCase : public testing::TestWithParam<std::tuple<int, float>> {};

}  // namespace

TEST_P(McMillanCase, drawsOccludingPairsBackToFrontAndEachPixelSorted) {
    const auto [index, depth] = GetParam();
    const Case& c = kCases[index];
    expectBackToFront({c.x, c.y}, depth, c.column, c.row);
}

// 9 epipole positions x (in front, behind) = the paper's 18 cases; "among"
// adds the in-front eye standing inside the point set.
INSTANTIATE_TEST_SUITE_P(NineByTwo, McMillanCase,
                         testing::Combine(testing::Range(0, 9), testing::Values(kInFront, kBehind, kAmong)));

TEST(McMillanOrder, eyeOnTheScreenPlaneSendsEpipoleFarOffScreen) {
    const LdiCamera cam = referenceCamera();
    const Epipole e = epipoleOf(cam, cam.eye + glm::vec3(5.0f, 0.0f, 0.0f));
    EXPECT_TRUE(e.column == EpipoleSide::Before || e.column == EpipoleSide::After);
    EXPECT_EQ(e.row, EpipoleSide::Inside);
}
