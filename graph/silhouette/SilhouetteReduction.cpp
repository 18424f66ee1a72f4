#include "graph/silhouette/SilhouetteReduction.hpp"

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace arcomp {

namespace {

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
    return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
}

// Sum of the triangles' edges as a chain: +1 for an edge running low to
// high index, -1 for the reverse; interior edges cancel. Sorted (edge,
// count) pairs with the zero counts left out.
std::vector<std::pair<std::uint64_t, int>> edgeChain(std::span<const std::uint32_t> indices) {
    std::vector<std::pair<std::uint64_t, int>> edges;
    edges.reserve(indices.size());
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = indices[t + k], b = indices[t + (k + 1) % 3];
            edges.push_back({edgeKey(a, b), a < b ? 1 : -1});
        }
    std::sort(edges.begin(), edges.end());
    std::vector<std::pair<std::uint64_t, int>> chain;
    for (std::size_t i = 0; i < edges.size();) {
        int sum = 0;
        std::size_t j = i;
        for (; j < edges.size() && edges[j].first == edges[i].first; ++j) sum += edges[j].second;
        if (sum != 0) chain.push_back({edges[i].first, sum});
        i = j;
    }
    return chain;
}

struct UnionFind {
    std::vector<std::uint32_t> parent;
    explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
    std::uint32_t find(std::uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    }
    void join(std::uint32_t a, std::uint32_t b) { parent[find(a)] = find(b); }
};

// Whether some line from a point of `eye` through a point of `tri` can meet
// `hole` on the triangle's side of the eye. Points on such a line are
// l*e + (1-l)*x with e, x in the spheres; they lie within
// |l|*eye.radius + |1-l|*tri.radius of l*eye.center + (1-l)*tri.center. The
// distance to the hole minus that margin is convex on l <= 0 and on
// 0 <= l <= 1, so a ternary search on each piece finds its minimum.
bool lineMayMeetHole(const Sphere& eye, const Sphere& tri, const Sphere& hole) {
    const glm::dvec3 ce(eye.center), ct(tri.center), ch(hole.center);
    const double gap = glm::length(ce - ct) - eye.radius - tri.radius;
    if (gap <= 0.0) return true;
    const double reach = glm::length(ch - ct) + hole.radius + tri.radius;
    const double lowest = -reach / gap - 1.0;
    auto excess = [&](double l) {
        const glm::dvec3 p = l * ce + (1.0 - l) * ct;
        return glm::length(ch - p) - hole.radius - std::abs(l) * eye.radius - std::abs(1.0 - l) * tri.radius;
    };
    for (const auto& [lo0, hi0] : {std::pair{lowest, 0.0}, std::pair{0.0, 1.0}}) {
        double lo = lo0, hi = hi0;
        for (int i = 0; i < 60; ++i) {
            const double m1 = lo + (hi - lo) / 3.0, m2 = hi - (hi - lo) / 3.0;
            if (excess(m1) < excess(m2))
                hi = m2;
            else
                lo = m1;
        }
        if (excess(0.5 * (lo + hi)) <= 1e-9 * reach || excess(lo0) <= 0.0 || excess(hi0) <= 0.0) return true;
    }
    return false;
}

Sphere triangleSphere(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 centre = (a + b + c) / 3.0f;
    const float r = std::max({glm::length(a - centre), glm::length(b - centre), glm::length(c - centre)});
    return {centre, r * 1.0001f + 1e-7f};
}

}  // namespace

std::vector<std::pair<std::uint32_t, std::uint32_t>> borderChain(std::span<const std::uint32_t> indices) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
    for (const auto& [key, count] : edgeChain(indices)) {
        const auto lo = static_cast<std::uint32_t>(key >> 32), hi = static_cast<std::uint32_t>(key);
        for (int i = 0; i < std::abs(count); ++i) out.push_back(count > 0 ? std::pair{lo, hi} : std::pair{hi, lo});
    }
    std::sort(out.begin(), out.end());
    return out;
}

bool allFrontFacing(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
                    std::span<const glm::vec3> eyes) {
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3)
        for (const glm::vec3& e : eyes)
            if (!frontFacingFrom(positions[indices[t]], positions[indices[t + 1]], positions[indices[t + 2]], e))
                return false;
    return true;
}

MeshHoles findHoles(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices) {
    MeshHoles holes;
    UnionFind loops(positions.size());
    std::vector<char> onBorder(positions.size(), 0);
    for (const auto& [from, to] : borderChain(indices)) {
        loops.join(from, to);
        onBorder[from] = onBorder[to] = 1;
        ++holes.borderEdges;
    }
    std::unordered_map<std::uint32_t, Box> boxes;
    for (std::uint32_t v = 0; v < positions.size(); ++v)
        if (onBorder[v]) boxes[loops.find(v)].expand(positions[v]);
    for (const auto& [root, box] : boxes) {
        Sphere s = sphereAround(box);
        s.radius = s.radius * 1.0001f + 1e-6f;
        holes.spheres.push_back(s);
    }
    return holes;
}

RegionReduction reduceForRegion(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
                                const ViewRegion& region, const MeshHoles& holes, const ReductionSettings& settings) {
    RegionReduction r;
    const std::span<const glm::vec3> eyes = region.vertices();
    const std::vector<Facing> facing = classifyTriangles(positions, indices, eyes);
    const Sphere eyeSphere = sphereAround(eyes);

    std::vector<std::uint32_t> frontTris, kept;
    for (std::uint32_t t = 0; t < facing.size(); ++t) {
        const std::uint32_t* tri = &indices[3 * t];
        switch (facing[t]) {
        case Facing::Front:
            ++r.front;
            frontTris.push_back(t);
            break;
        case Facing::Silhouette:
            ++r.silhouette;
            kept.insert(kept.end(), tri, tri + 3);
            break;
        case Facing::Back: {
            ++r.back;
            const Sphere s = triangleSphere(positions[tri[0]], positions[tri[1]], positions[tri[2]]);
            const bool seen = std::any_of(holes.spheres.begin(), holes.spheres.end(),
                                          [&](const Sphere& h) { return lineMayMeetHole(eyeSphere, s, h); });
            if (seen) {
                ++r.backKept;
                kept.insert(kept.end(), tri, tri + 3);
            }
            break;
        }
        }
    }

    // Simplify the unlocked part of FM; on a rejected result lock the FM
    // triangles around each failure and retry; every triesPerRing tries the
    // locked zone grows by one more ring, so that stubborn spots end soon.
    std::vector<char> locked(frontTris.size(), 0);
    std::vector<std::uint32_t> input, output;
    for (int attempt = 0;; ++attempt) {
        input.clear();
        for (std::size_t i = 0; i < frontTris.size(); ++i)
            if (!locked[i]) input.insert(input.end(), &indices[3 * frontTris[i]], &indices[3 * frontTris[i] + 3]);
        if (attempt >= settings.maxTries || input.empty()) {
            output = input;
            break;
        }
        output.resize(input.size());
        const std::size_t n =
            meshopt_simplify(output.data(), input.data(), input.size(), &positions[0].x, positions.size(),
                             sizeof(glm::vec3), 0, settings.targetError, meshopt_SimplifyLockBorder, nullptr);
        output.resize(n);

        std::vector<char> marked(positions.size(), 0);
        bool failed = false;
        for (std::size_t t = 0; t < output.size(); t += 3) {
            if (allFrontFacing(positions, std::span(output).subspan(t, 3), eyes)) continue;
            failed = true;
            for (int k = 0; k < 3; ++k) marked[output[t + k]] = 1;
        }
        const auto before = borderChain(input), after = borderChain(output);
        if (before != after) {
            failed = true;
            std::vector<std::pair<std::uint32_t, std::uint32_t>> diff;
            std::set_symmetric_difference(before.begin(), before.end(), after.begin(), after.end(),
                                          std::back_inserter(diff));
            for (const auto& [a, b] : diff) marked[a] = marked[b] = 1;
        }
        if (!failed) break;
        ++r.rejectedTries;
        for (int ring = 0; ring <= attempt / settings.triesPerRing; ++ring) {
            std::vector<std::uint32_t> grown;
            for (std::size_t i = 0; i < frontTris.size(); ++i) {
                if (locked[i]) continue;
                const std::uint32_t* tri = &indices[3 * frontTris[i]];
                if (marked[tri[0]] || marked[tri[1]] || marked[tri[2]]) {
                    locked[i] = 1;
                    grown.insert(grown.end(), tri, tri + 3);
                }
            }
            for (std::uint32_t v : grown) marked[v] = 1;
        }
    }
    r.frontLocked = static_cast<std::size_t>(std::count(locked.begin(), locked.end(), 1));
    r.frontAfter = output.size() / 3 + r.frontLocked;

    r.indices = std::move(output);
    for (std::size_t i = 0; i < frontTris.size(); ++i)
        if (locked[i]) r.indices.insert(r.indices.end(), &indices[3 * frontTris[i]], &indices[3 * frontTris[i] + 3]);
    r.indices.insert(r.indices.end(), kept.begin(), kept.end());
    return r;
}

}  // namespace arcomp
