#include "graph/LdiRenderer.hpp"

#include "graph/McMillanOrder.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <thread>

namespace arcomp {

namespace {

constexpr float kMinRadius = 0.71f;      // reaches the nearest pixel centre from anywhere
constexpr float kFootprint = 0.71f;      // half a face's diagonal, in point sizes: closes the gaps of a square grid
constexpr float kRimFalloff = 0.6f;      // weight 1 at the centre, 0.4 at the rim

// Without SSE4.1 (the x86-64 baseline) std::floor is a library call; these
// run once per splatted point.
int floorToInt(float v) {
    const int i = static_cast<int>(v);
    return i - (static_cast<float>(i) > v);
}
int ceilToInt(float v) {
    const int i = static_cast<int>(v);
    return i + (static_cast<float>(i) < v);
}

std::uint8_t toByte(float v) { return static_cast<std::uint8_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); }

} // namespace

std::size_t PointImage::coveredPixels() const {
    std::size_t n = 0;
    for (std::size_t i = 3; i < rgba.size(); i += 4) n += rgba[i] != 0;
    return n;
}

LdiRenderer::LdiRenderer(const LdiSet& set, int threads) : set_(set), threads_(std::max(1, threads)) {}

template <class F> void LdiRenderer::parallel(F&& f) {
    std::vector<std::thread> helpers;
    for (int t = 1; t < threads_; ++t) helpers.emplace_back([&f, t, this] { f(t, threads_); });
    f(0, threads_);
    for (std::thread& h : helpers) h.join();
}

void LdiRenderer::project(const View& view) {
    const std::size_t n = set_.cloud.size();
    image_.width = view.viewport.x;
    image_.height = view.viewport.y;
    screen_.resize(n);
    depth_.resize(n);
    radius_.resize(n);
    const glm::mat4 viewProjection = view.viewProjection();
    const float pixelScale = view.pixelScale();
    const float footprint = kFootprint * set_.cloud.pointSize * pixelScale;
    const glm::vec2 size(image_.width, image_.height);
    parallel([&](int worker, int workers) {
        for (std::size_t i = n * static_cast<std::size_t>(worker) / static_cast<std::size_t>(workers),
                         end = n * static_cast<std::size_t>(worker + 1) / static_cast<std::size_t>(workers);
             i < end; ++i) {
            const glm::vec3& p = set_.cloud.positions[i];
            const float z = glm::dot(p - view.eye, view.forward);
            if (!(z > view.near) || z > view.far) {
                depth_[i] = -1.0f;  // not drawn
                continue;
            }
            const glm::vec4 clip = viewProjection * glm::vec4(p, 1.0f);
            screen_[i] = glm::vec2(clip.x / clip.w * 0.5f + 0.5f, 0.5f - clip.y / clip.w * 0.5f) * size;
            depth_[i] = z;
            radius_[i] = std::max(kMinRadius, footprint / z);
        }
    });
}

// Calls emit(pixel, entry) for each pixel of the point's footprint within
// rows [rowLo, rowHi).
template <class Emit>
void LdiRenderer::footprint(std::uint32_t id, std::uint8_t ldi, int rowLo, int rowHi, Emit&& emit) const {
    if (depth_[id] < 0.0f) return;
    const int w = image_.width;
    const glm::vec2 s = screen_[id];
    const float r = radius_[id], r2 = r * r, invR2 = kRimFalloff / r2;
    // Off-screen points would overflow int; they reach no pixel anyway.
    if (s.x + r < 0.0f || s.y + r < static_cast<float>(rowLo) || s.x - r > static_cast<float>(w) ||
        s.y - r > static_cast<float>(rowHi))
        return;
    const int x0 = std::max(0, ceilToInt(s.x - r - 0.5f));
    const int x1 = std::min(w - 1, floorToInt(s.x + r - 0.5f));
    const int y0 = std::max(rowLo, ceilToInt(s.y - r - 0.5f));
    const int y1 = std::min(rowHi - 1, floorToInt(s.y + r - 0.5f));
    if (y0 > y1 || x0 > x1) return;
    const glm::vec4 c = set_.cloud.colors[id];
    const glm::u8vec4 colorLdi(glm::round(glm::clamp(glm::vec3(c), 0.0f, 1.0f) * 255.0f), ldi);
    const float z = depth_[id];
    for (int y = y0; y <= y1; ++y) {
        const float dy = static_cast<float>(y) + 0.5f - s.y;
        for (int x = x0; x <= x1; ++x) {
            const float dx = static_cast<float>(x) + 0.5f - s.x;
            const float d2 = dx * dx + dy * dy;
            if (d2 <= r2) emit(static_cast<std::uint32_t>(y * w + x), Entry{z, c.a * (1.0f - d2 * invR2), colorLdi});
        }
    }
}

void LdiRenderer::splat(const std::vector<std::uint32_t>& ids, std::size_t begin, std::size_t end, std::uint8_t ldi,
                        std::vector<Splat>& out) const {
    for (std::size_t k = begin; k < end; ++k)
        footprint(ids[k], ldi, 0, image_.height, [&out](std::uint32_t pixel, const Entry& e) { out.push_back({pixel, e}); });
}

// One stream already in back-to-front order needs no buffers: splats are
// composited as they come. Each thread owns a band of rows and walks the
// whole stream, which keeps the order without any locking.
void LdiRenderer::compositeInOrder(const std::vector<std::uint32_t>& ids) {
    const std::size_t pixels = static_cast<std::size_t>(image_.width) * static_cast<std::size_t>(image_.height);
    image_.rgba.resize(pixels * 4);
    image_.depth.resize(pixels);
    accumulators_.resize(pixels);
    std::vector<std::size_t> counts(static_cast<std::size_t>(threads_), 0);
    parallel([&](int worker, int workers) {
        const int y0 = image_.height * worker / workers, y1 = image_.height * (worker + 1) / workers;
        const std::size_t p0 = static_cast<std::size_t>(y0) * static_cast<std::size_t>(image_.width);
        const std::size_t p1 = static_cast<std::size_t>(y1) * static_cast<std::size_t>(image_.width);
        std::fill(accumulators_.begin() + static_cast<std::ptrdiff_t>(p0), accumulators_.begin() + static_cast<std::ptrdiff_t>(p1),
                  Accumulator{});
        std::size_t n = 0;
        for (std::uint32_t id : ids)
            footprint(id, 0, y0, y1, [&](std::uint32_t pixel, const Entry& e) {
                accumulators_[pixel].over(e.colorLdi, e.alpha, e.depth);
                ++n;
            });
        counts[static_cast<std::size_t>(worker)] = n;
        for (std::size_t p = p0; p < p1; ++p) store(p, accumulators_[p]);
    });
    splatCount_ = 0;
    for (std::size_t n : counts) splatCount_ += n;
}

inline void LdiRenderer::store(std::size_t p, const Accumulator& acc) {
    std::uint8_t* out = &image_.rgba[p * 4];
    for (int c = 0; c < 3; ++c) out[c] = toByte(acc.color[c]);
    out[3] = toByte(acc.alpha);
    image_.depth[p] = acc.depth;
}

void LdiRenderer::gather(std::size_t streams) {
    const std::size_t pixels = static_cast<std::size_t>(image_.width) * static_cast<std::size_t>(image_.height);
    pixelStart_.assign(pixels + 1, 0);
    std::size_t total = 0;
    for (std::size_t s = 0; s < streams; ++s) {
        total += splats_[s].size();
        for (const Splat& sp : splats_[s]) ++pixelStart_[sp.pixel + 1];
    }
    std::partial_sum(pixelStart_.begin(), pixelStart_.end(), pixelStart_.begin());
    sorted_.resize(total);
    // Stable: within a pixel, stream 0's splats keep their order, then stream 1's, ...
    for (std::size_t s = 0; s < streams; ++s)
        for (const Splat& sp : splats_[s]) sorted_[pixelStart_[sp.pixel]++] = sp.entry;
    // Each start now holds its pixel's end; shift back.
    for (std::size_t p = pixels; p > 0; --p) pixelStart_[p] = pixelStart_[p - 1];
    pixelStart_[0] = 0;
}

void LdiRenderer::compositeRows(int y0, int y1, bool merge) {
    struct Run {
        std::uint32_t next, end;
    };
    std::vector<Run> runs;
    runs.reserve(set_.ldis.size());
    for (std::size_t p = static_cast<std::size_t>(y0) * static_cast<std::size_t>(image_.width),
                     last = static_cast<std::size_t>(y1) * static_cast<std::size_t>(image_.width);
         p < last; ++p) {
        const std::uint32_t begin = pixelStart_[p], end = pixelStart_[p + 1];
        std::uint8_t* out = &image_.rgba[p * 4];
        if (begin == end) {
            out[0] = out[1] = out[2] = out[3] = 0;
            image_.depth[p] = std::numeric_limits<float>::infinity();
            continue;
        }
        Accumulator acc;
        if (!merge) {
            for (std::uint32_t k = begin; k < end; ++k)
                acc.over(sorted_[k].colorLdi, sorted_[k].alpha, sorted_[k].depth);
        } else {
            // The n projection buffers' runs for this pixel, each back to front.
            runs.clear();
            std::uint32_t start = begin;
            for (std::uint32_t k = begin + 1; k <= end; ++k) {
                if (k == end || sorted_[k].colorLdi.w != sorted_[k - 1].colorLdi.w) {
                    runs.push_back({start, k});
                    start = k;
                }
            }
            while (!runs.empty()) {
                std::size_t pick = 0;
                float deepest = sorted_[runs[0].next].depth;
                for (std::size_t r = 1; r < runs.size(); ++r) {
                    const float d = sorted_[runs[r].next].depth;
                    if (d > deepest) deepest = d, pick = r;
                }
                const Entry& e = sorted_[runs[pick].next];
                acc.over(e.colorLdi, e.alpha, e.depth);
                if (++runs[pick].next == runs[pick].end) {
                    runs[pick] = runs.back();
                    runs.pop_back();
                }
            }
        }
        store(p, acc);
    }
}

void LdiRenderer::composite(bool merge) {
    const std::size_t pixels = static_cast<std::size_t>(image_.width) * static_cast<std::size_t>(image_.height);
    image_.rgba.resize(pixels * 4);
    image_.depth.resize(pixels);
    parallel([&](int worker, int workers) {
        compositeRows(image_.height * worker / workers, image_.height * (worker + 1) / workers, merge);
    });
}

const PointImage& LdiRenderer::render(const View& view) {
    project(view);
    const std::size_t n = set_.ldis.size();
    order_.resize(std::max<std::size_t>(order_.size(), n));
    splats_.resize(std::max<std::size_t>(splats_.size(), n));
    parallel([&](int worker, int workers) {
        for (std::size_t l = static_cast<std::size_t>(worker); l < n; l += static_cast<std::size_t>(workers)) {
            order_[l].clear();
            appendBackToFront(set_.ldis[l], view.eye, order_[l]);
            if (n == 1) continue;
            splats_[l].clear();
            splat(order_[l], 0, order_[l].size(), static_cast<std::uint8_t>(l), splats_[l]);
        }
    });
    if (n == 1) {
        compositeInOrder(order_[0]);
        return image_;
    }
    gather(n);
    splatCount_ = sorted_.size();
    composite(true);
    return image_;
}

const PointImage& LdiRenderer::renderDepthSorted(const View& view) {
    project(view);
    byDepth_.clear();
    for (std::size_t i = 0; i < depth_.size(); ++i)
        if (depth_[i] >= 0.0f) byDepth_.emplace_back(depth_[i], static_cast<std::uint32_t>(i));
    std::sort(byDepth_.begin(), byDepth_.end(), std::greater<>());
    order_.resize(std::max<std::size_t>(order_.size(), 1));
    order_[0].clear();
    for (const auto& [z, id] : byDepth_) order_[0].push_back(id);
    compositeInOrder(order_[0]);
    return image_;
}

} // namespace arcomp
