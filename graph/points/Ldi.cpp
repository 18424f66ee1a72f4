#include "graph/points/Ldi.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace arcomp {

LdiPlacement placeInLdi(const LdiCamera& camera, const glm::vec3& p) {
    const glm::vec3 q = camera.toCamera(p);
    if (!(q.z > 0.0f)) return {};
    const glm::vec2 screen = glm::vec2(q.x, q.y) / q.z * camera.focal + camera.principal();
    const float x = std::clamp(std::floor(screen.x), 0.0f, static_cast<float>(camera.width - 1));
    const float y = std::clamp(std::floor(screen.y), 0.0f, static_cast<float>(camera.height - 1));
    const float lp = glm::length(screen - glm::vec2(x + 0.5f, y + 0.5f));
    const auto pixel =
        static_cast<std::uint32_t>(y) * static_cast<std::uint32_t>(camera.width) + static_cast<std::uint32_t>(x);
    return {pixel, rayDistanceLx(q.z, lp, camera.focal), true};
}

LdiSet buildLdis(PointCloud cloud, std::vector<LdiCamera> cameras) {
    if (cameras.empty() || cameras.size() >= kNoLdi)
        throw std::invalid_argument("buildLdis: need between 1 and 254 cameras");
    LdiSet set;
    set.cloud = std::move(cloud);
    const std::size_t n = set.cloud.size();
    set.pointLdi.assign(n, kNoLdi);
    std::vector<std::uint32_t> pointPixel(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        float best = std::numeric_limits<float>::infinity();
        for (std::size_t c = 0; c < cameras.size(); ++c) {
            const LdiPlacement placed = placeInLdi(cameras[c], set.cloud.positions[i]);
            if (placed.valid && placed.lx < best) {
                best = placed.lx;
                set.pointLdi[i] = static_cast<std::uint8_t>(c);
                pointPixel[i] = placed.pixel;
            }
        }
        if (set.pointLdi[i] == kNoLdi) ++set.unregistered;
    }
    set.ldis.resize(cameras.size());
    for (std::size_t c = 0; c < cameras.size(); ++c) {
        Ldi& ldi = set.ldis[c];
        ldi.camera = cameras[c];
        const std::size_t pixels =
            static_cast<std::size_t>(ldi.camera.width) * static_cast<std::size_t>(ldi.camera.height);
        // Counting sort by pixel, then each pixel's short run by depth.
        ldi.pixelStart.assign(pixels + 1, 0);
        for (std::size_t i = 0; i < n; ++i)
            if (set.pointLdi[i] == c) ++ldi.pixelStart[pointPixel[i] + 1];
        std::partial_sum(ldi.pixelStart.begin(), ldi.pixelStart.end(), ldi.pixelStart.begin());
        ldi.points.resize(ldi.pixelStart[pixels]);
        ldi.rayDepth.resize(ldi.points.size());
        std::vector<std::uint32_t> cursor(ldi.pixelStart.begin(), ldi.pixelStart.end() - 1);
        for (std::size_t i = 0; i < n; ++i)
            if (set.pointLdi[i] == c) ldi.points[cursor[pointPixel[i]]++] = static_cast<std::uint32_t>(i);
        std::vector<std::pair<float, std::uint32_t>> run;
        for (std::size_t p = 0; p < pixels; ++p) {
            const std::uint32_t begin = ldi.pixelStart[p], end = ldi.pixelStart[p + 1];
            if (begin == end) continue;
            const int px = static_cast<int>(p % static_cast<std::size_t>(ldi.camera.width));
            const int py = static_cast<int>(p / static_cast<std::size_t>(ldi.camera.width));
            const glm::vec3 ray = ldi.camera.rayDirection(px, py);
            run.clear();
            for (std::uint32_t k = begin; k < end; ++k)
                run.emplace_back(glm::dot(set.cloud.positions[ldi.points[k]] - ldi.camera.eye, ray), ldi.points[k]);
            std::sort(run.begin(), run.end());
            for (std::uint32_t k = begin; k < end; ++k) {
                ldi.rayDepth[k] = run[k - begin].first;
                ldi.points[k] = run[k - begin].second;
            }
        }
    }
    return set;
}

}  // namespace arcomp
