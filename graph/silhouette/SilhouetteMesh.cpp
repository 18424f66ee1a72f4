#include "graph/silhouette/SilhouetteMesh.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <map>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <tuple>

namespace arcomp {

int SilhouetteMesh::regionAt(const glm::vec3& eye) const {
    for (std::size_t i = 0; i < regions.size(); ++i)
        if (regions[i].contains(eye)) return static_cast<int>(i);
    return -1;
}

SilhouetteRange SilhouetteMesh::rangeFor(const glm::vec3& eye) const {
    const int r = regionAt(eye);
    return r < 0 ? full : ranges[static_cast<std::size_t>(r)];
}

Geometry SilhouetteMesh::geometry() const {
    Geometry g;
    g.positions = positions;
    g.indices = indices;
    // Normals from the full mesh alone: the region lists repeat its
    // triangles and would weigh them several times.
    g.normals = computeVertexNormals(positions, {indices.begin(), indices.begin() + full.indexCount});
    g.finalize();
    return g;
}

FlatWeld weldPositions(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices) {
    if (indices.size() % 3 != 0) throw std::invalid_argument("index count is not a multiple of 3");
    FlatWeld m;
    std::map<std::tuple<float, float, float>, std::uint32_t> welded;
    std::vector<std::uint32_t> remap(positions.size());
    for (std::size_t v = 0; v < positions.size(); ++v) {
        const glm::vec3 p = positions[v];
        const auto [it, fresh] = welded.try_emplace({p.x, p.y, p.z}, static_cast<std::uint32_t>(m.positions.size()));
        if (fresh) m.positions.push_back(p);
        remap[v] = it->second;
    }
    for (std::size_t t = 0; t < indices.size(); t += 3) {
        std::uint32_t tri[3];
        for (int k = 0; k < 3; ++k) {
            if (indices[t + k] >= positions.size()) throw std::invalid_argument("index out of range");
            tri[k] = remap[indices[t + k]];
        }
        // Welding can collapse a sliver; a degenerate triangle covers nothing.
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;
        m.indices.insert(m.indices.end(), tri, tri + 3);
    }
    return m;
}

SilhouetteMesh bakeSilhouetteMesh(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
                                  std::vector<ViewRegion> regions, std::vector<SilhouetteRegionReport>* report,
                                  const BakeProgress& progress) {
    if (indices.size() % 3 != 0) throw std::invalid_argument("index count is not a multiple of 3");
    SilhouetteMesh m;
    FlatWeld w = weldPositions(positions, indices);
    m.positions = std::move(w.positions);
    m.indices = std::move(w.indices);
    m.full = {0, static_cast<std::uint32_t>(m.indices.size())};
    const std::vector<std::uint32_t> fullIndices = m.indices;
    const MeshHoles holes = findHoles(m.positions, fullIndices);
    m.regions = std::move(regions);
    if (report) report->clear();

    // Regions are independent: one worker per core takes the next region.
    // Each result lands in its own slot, so the output does not depend on
    // the schedule.
    std::vector<RegionReduction> results(m.regions.size());
    std::atomic<std::size_t> next{0};
    std::size_t done = 0;
    std::mutex progressLock;
    std::exception_ptr failure;
    auto work = [&] {
        for (std::size_t i; (i = next++) < results.size();) {
            try {
                results[i] = reduceForRegion(m.positions, fullIndices, m.regions[i], holes);
            } catch (...) {
                const std::lock_guard lock(progressLock);
                if (!failure) failure = std::current_exception();
            }
            const std::lock_guard lock(progressLock);
            ++done;
            if (progress) progress(done, results.size());
        }
    };
    const std::size_t workers =
        std::min<std::size_t>(std::max(1u, std::thread::hardware_concurrency()), results.size());
    std::vector<std::thread> threads;
    for (std::size_t w = 1; w < workers; ++w) threads.emplace_back(work);
    work();
    for (std::thread& t : threads) t.join();
    if (failure) std::rethrow_exception(failure);

    for (const RegionReduction& r : results) {
        m.ranges.push_back(
            {static_cast<std::uint32_t>(m.indices.size()), static_cast<std::uint32_t>(r.indices.size())});
        m.indices.insert(m.indices.end(), r.indices.begin(), r.indices.end());
        if (report)
            report->push_back({r.front, r.back, r.silhouette, r.backKept, r.frontAfter, r.frontLocked, r.rejectedTries,
                               r.trianglesBefore(), r.trianglesAfter()});
    }
    return m;
}

}  // namespace arcomp
