#include "graph/points/LdiRenderer.hpp"

#include "graph/core/ElapsedTime.hpp"
#include "graph/points/McMillanOrder.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <numeric>
#include <thread>

namespace arcomp {

namespace {

constexpr float kMinRadius = 0.71f;  // reaches the nearest pixel centre from anywhere
constexpr float kFootprint = 0.71f;  // half a face's diagonal, in point sizes: closes the gaps of a square grid
constexpr float kRimFalloff = 0.6f;  // weight 1 at the centre, 0.4 at the rim

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

using Float4 = LdiRenderer::Float4;
using Int4 = std::int32_t __attribute__((vector_size(16)));

// Each lane clamped to [0, 1] and rounded to the nearest of 0..255.
Int4 toBytes(Float4 v) {
    v = v * 255.0f + 0.5f;
    v = v < 0.0f ? Float4{} : v;
    v = v > 255.0f ? Float4{} + 255.0f : v;
    return __builtin_convertvector(v, Int4);
}

// Bytes 0..255 of R, G, B and A as one RGBA8 pixel in memory order (lanes
// of four pixels at once, or one); stored through memcpy, not byte by byte,
// which stalled on reading back what had just been written.
template <class T>
T packRgba8(T r, T g, T b, T a) {
    static_assert(std::endian::native == std::endian::little, "RGBA8 packing assumes a little-endian machine");
    return r | g << 8 | b << 16 | a << 24;
}

// A frame's phases last a fraction of a millisecond. With std::barrier,
// which puts a waiting thread to sleep, the helper finished its band about
// 0.15 ms after worker 0 with the same number of splats (it had waited out
// the one LDI's walk asleep). This barrier spins, yielding so that a busy
// machine loses little; the last to arrive runs the completion step before
// anyone leaves.
class SpinBarrier {
public:
    explicit SpinBarrier(int count) : count_(count) {}
    template <class Completion>
    void arriveAndWait(Completion&& completion) {
        const unsigned phase = phase_.load(std::memory_order_acquire);
        if (arrived_.fetch_add(1, std::memory_order_acq_rel) + 1 == count_) {
            completion();
            arrived_.store(0, std::memory_order_relaxed);
            phase_.store(phase + 1, std::memory_order_release);
            return;
        }
        while (phase_.load(std::memory_order_acquire) == phase) std::this_thread::yield();
    }
    void arriveAndWait() {
        arriveAndWait([] {});
    }

private:
    const int count_;
    std::atomic<int> arrived_{0};
    std::atomic<unsigned> phase_{0};
};

}  // namespace

std::size_t PointImage::coveredPixels() const {
    std::size_t n = 0;
    for (std::size_t i = 3; i < rgba.size(); i += 4) n += rgba[i] != 0;
    return n;
}

LdiRenderer::LdiRenderer(const LdiSet& set, int threads)
    : set_(set), threads_(std::max(1, threads)), pool_(static_cast<std::size_t>(threads_)) {
    const PointCloud& cloud = set_.cloud;
    const auto add = [&](Items& items, std::uint32_t id, std::size_t ldi) {
        const glm::vec4& c = cloud.colors[id];
        const glm::u8vec4 rgb8(glm::round(glm::clamp(glm::vec3(c), 0.0f, 1.0f) * 255.0f),
                               static_cast<std::uint8_t>(ldi));
        items.positions.push_back(cloud.positions[id]);
        items.colors.push_back(rgb8);
        items.alphas.push_back(c.a);
        items.premultiplied.push_back(Accumulator::premultiply(rgb8, c.a));
    };
    for (std::uint32_t id = 0; id < cloud.positions.size(); ++id) add(points_, id, 0);
    for (std::size_t l = 0; l < set_.ldis.size(); ++l) {
        slotBase_.push_back(static_cast<std::uint32_t>(slots_.positions.size()));
        for (std::uint32_t id : set_.ldis[l].points) add(slots_, id, l);
    }
}

void LdiRenderer::project(const View& view, std::size_t worker) {
    const std::size_t n = items_->positions.size(), workers = bands_.size();
    const glm::mat4 viewProjection = view.viewProjection();
    const float footprint = kFootprint * set_.cloud.pointSize * view.pixelScale();
    const glm::vec2 size(image_.width, image_.height);
    std::vector<float>& rows = bands_[worker].rowWeight;
    rows.assign(static_cast<std::size_t>(image_.height), 0.0f);
    float reach0 = size.y, reach1 = 0.0f;
    for (std::size_t i = n * worker / workers, end = n * (worker + 1) / workers; i < end; ++i) {
        const glm::vec3& p = items_->positions[i];
        const float z = glm::dot(p - view.eye, view.forward);
        if (!(z > view.near) || z > view.far) {
            projected_[i].depth = -1.0f;  // not drawn
            continue;
        }
        const glm::vec4 clip = viewProjection * glm::vec4(p, 1.0f);
        const glm::vec2 s = glm::vec2(clip.x / clip.w * 0.5f + 0.5f, 0.5f - clip.y / clip.w * 0.5f) * size;
        const float r = std::max(kMinRadius, footprint / z);
        projected_[i] = {s, z, r};
        // About how many splats the point makes, in the row of its centre.
        if (s.x + r >= 0.0f && s.x - r <= size.x) {
            if (s.y >= 0.0f && s.y < size.y) rows[static_cast<std::size_t>(s.y)] += 1.0f + 3.0f * r * r;
            reach0 = std::min(reach0, s.y - r - 1.0f);
            reach1 = std::max(reach1, s.y + r + 1.0f);
        }
    }
    bands_[worker].reach0 = static_cast<int>(std::clamp(reach0, 0.0f, size.y));
    bands_[worker].reach1 = static_cast<int>(std::clamp(reach1, 0.0f, size.y));
}

// Cuts the rows into one band per thread with about equal splat weight.
void LdiRenderer::cutBands() {
    const std::size_t workers = bands_.size();
    std::vector<float>& total = bands_[0].rowWeight;
    for (std::size_t w = 1; w < workers; ++w)
        for (std::size_t y = 0; y < total.size(); ++y) total[y] += bands_[w].rowWeight[y];
    const float sum = std::accumulate(total.begin(), total.end(), 0.0f);
    int reach0 = image_.height, reach1 = 0;
    for (const Band& b : bands_) {
        reach0 = std::min(reach0, b.reach0);
        reach1 = std::max(reach1, b.reach1);
    }
    float running = 0.0f;
    std::size_t band = 0;
    bands_[0].y0 = 0;
    for (int y = 0; y < image_.height && band + 1 < workers; ++y) {
        running += total[static_cast<std::size_t>(y)];
        if (running >= sum * static_cast<float>(band + 1) / static_cast<float>(workers)) {
            bands_[band].y1 = y + 1;
            bands_[++band].y0 = y + 1;
        }
    }
    for (; band < workers; ++band) {
        bands_[band].y1 = image_.height;
        if (band + 1 < workers) bands_[band + 1].y0 = image_.height;
    }
    for (Band& b : bands_) {
        b.reach0 = std::clamp(reach0, b.y0, b.y1);
        b.reach1 = std::clamp(reach1, b.reach0, b.y1);
    }
}

// Rows no splat reaches are cleared in bulk, not pixel by pixel.
void LdiRenderer::clearRowsOutsideReach(const Band& band) {
    const std::size_t w = static_cast<std::size_t>(image_.width);
    for (const auto& [a, b] : {std::pair{band.y0, band.reach0}, std::pair{band.reach1, band.y1}}) {
        const std::size_t p0 = static_cast<std::size_t>(a) * w, p1 = static_cast<std::size_t>(b) * w;
        if (p0 >= p1) continue;
        std::fill(image_.rgba.begin() + static_cast<std::ptrdiff_t>(p0 * 4),
                  image_.rgba.begin() + static_cast<std::ptrdiff_t>(p1 * 4), 0);
        std::fill(image_.depth.begin() + static_cast<std::ptrdiff_t>(p0),
                  image_.depth.begin() + static_cast<std::ptrdiff_t>(p1), std::numeric_limits<float>::infinity());
    }
}

// The pixels whose centres may lie in the point's disc: those of its
// bounding square, within rows [rowLo, rowHi) and the image. False when it
// is not drawn or reaches none of them.
inline bool LdiRenderer::reach(std::uint32_t id, int rowLo, int rowHi, PixelBox& box) const {
    const Projected& q = projected_[id];
    if (q.depth < 0.0f) return false;
    const glm::vec2 s = q.screen;
    const float r = q.radius;
    // Off-screen points would overflow int; they reach no pixel anyway.
    if (s.x + r < 0.0f || s.y + r < static_cast<float>(rowLo) || s.x - r > static_cast<float>(image_.width) ||
        s.y - r > static_cast<float>(rowHi))
        return false;
    // Clamped before they become ints: a huge footprint would overflow.
    box.y0 = ceilToInt(std::max(s.y - r - 0.5f, static_cast<float>(rowLo)));
    box.y1 = floorToInt(std::min(s.y + r - 0.5f, static_cast<float>(rowHi - 1)));
    box.x0 = ceilToInt(std::max(s.x - r - 0.5f, 0.0f));
    box.x1 = floorToInt(std::min(s.x + r - 0.5f, static_cast<float>(image_.width - 1)));
    return true;
}

// Calls span(y, xa, xb, dy) for each row y within [rowLo, rowHi) that the
// point's footprint reaches, covering the pixels xa..xb of that row whose
// centres lie in the disc (dy: the row centre's offset from the point).
// Solving the disc for each row's ends leaves no per-pixel test, whose
// branch mispredicted about as often as it was taken.
template <class Span>
void LdiRenderer::rowSpans(std::uint32_t id, int rowLo, int rowHi, Span&& span) const {
    PixelBox box;
    if (!reach(id, rowLo, rowHi, box)) return;
    const int w = image_.width;
    const glm::vec2 s = projected_[id].screen;
    const float r2 = projected_[id].radius * projected_[id].radius;
    for (int y = box.y0; y <= box.y1; ++y) {
        const float dy = static_cast<float>(y) + 0.5f - s.y;
        const float h2 = r2 - dy * dy;
        if (h2 < 0.0f) continue;
        const float half = std::sqrt(h2);
        const int xa = ceilToInt(std::max(s.x - half - 0.5f, 0.0f));
        const int xb = floorToInt(std::min(s.x + half - 0.5f, static_cast<float>(w - 1)));
        if (xa <= xb) span(y, xa, xb, dy);
    }
}

// Calls emit(pixel, weight) for each pixel of the point's footprint within
// rows [rowLo, rowHi).
template <class Emit>
void LdiRenderer::footprint(std::uint32_t id, int rowLo, int rowHi, Emit&& emit) const {
    const float sx = projected_[id].screen.x, invR2 = kRimFalloff / (projected_[id].radius * projected_[id].radius);
    const auto w = static_cast<std::uint32_t>(image_.width);
    rowSpans(id, rowLo, rowHi, [&](int y, int xa, int xb, float dy) {
        const float dy2 = dy * dy;
        const std::uint32_t row = static_cast<std::uint32_t>(y) * w;
        for (int x = xa; x <= xb; ++x) {
            const float dx = static_cast<float>(x) + 0.5f - sx;
            emit(row + static_cast<std::uint32_t>(x), 1.0f - (dx * dx + dy2) * invR2);
        }
    });
}

// One stream already in back-to-front order needs no buffers: splats are
// composited as they come. Each thread owns a band of rows and walks the
// whole stream, which keeps the order without any locking.
//
// A splat covers a few pixels in each of a few rows, a different number for
// each point: walking them one by one mispredicted a branch at the end of
// nearly every row. Here the colour channels lie in planes, and four
// neighbouring pixels of a row are composited at once, the pixels outside
// the disc with weight 0, which "over" leaves as they were. Rows are
// kPlanePad pixels wider than the image, so that the last group of a row
// never reaches into the next (another thread's, at a band's edge).
void LdiRenderer::compositeInOrder(Band& band, const std::vector<std::uint32_t>& ids) {
    const auto load = [](const float* p) {
        Float4 v;
        std::memcpy(&v, p, sizeof v);
        return v;
    };
    const auto save = [](float* p, Float4 v) { std::memcpy(p, &v, sizeof v); };
    clearRowsOutsideReach(band);
    const int w = image_.width, rowLo = band.reach0, rowHi = band.reach1;
    const std::size_t stride = static_cast<std::size_t>(w + kPlanePad), rows = static_cast<std::size_t>(rowHi - rowLo);
    const std::size_t plane = rows * stride;
    band.planes.assign(plane * 5, 0.0f);
    std::fill(band.planes.begin() + static_cast<std::ptrdiff_t>(plane * 4), band.planes.end(),
              std::numeric_limits<float>::infinity());
    float* const r = band.planes.data() - static_cast<std::size_t>(rowLo) * stride;
    float *const g = r + plane, *const b = g + plane, *const a = b + plane, *const depth = a + plane;
    const Float4 lane{0.5f, 1.5f, 2.5f, 3.5f};
    std::size_t n = 0;
    for (std::uint32_t id : ids) {
        PixelBox box;
        if (!reach(id, rowLo, rowHi, box)) continue;
        const Projected& q = projected_[id];
        const glm::vec2 s = q.screen;
        const float r2 = q.radius * q.radius, invR2 = kRimFalloff / r2, z = q.depth;
        const Float4 src = items_->premultiplied[id];
        const int x1 = box.x1;
        for (int x = box.x0; x <= x1; x += 4) {
            const Float4 dx = lane + static_cast<float>(x) - s.x;
            const Float4 dx2 = dx * dx;
            const Int4 inRow = Int4{0, 1, 2, 3} + x <= x1;
            for (int y = box.y0; y <= box.y1; ++y) {
                const float dy = static_cast<float>(y) + 0.5f - s.y;
                const Float4 d2 = dx2 + dy * dy;
                const Int4 inside = (d2 <= r2) & inRow;
                const Float4 weight = inside ? 1.0f - d2 * invR2 : Float4{};
                const Float4 alpha = weight * src[3], keep = 1.0f - alpha;
                const std::size_t at = static_cast<std::size_t>(y) * stride + static_cast<std::size_t>(x);
                save(r + at, load(r + at) * keep + weight * src[0]);
                save(g + at, load(g + at) * keep + weight * src[1]);
                save(b + at, load(b + at) * keep + weight * src[2]);
                save(a + at, load(a + at) * keep + alpha);
                const Float4 d = load(depth + at);
                save(depth + at, inside && z < d ? Float4{} + z : d);
                n += static_cast<std::size_t>(-(inside[0] + inside[1] + inside[2] + inside[3]));  // lanes in: -1
            }
        }
    }
    band.splats = n;
    // Four pixels at a time into the image; the padding is read, not written.
    for (int y = rowLo; y < rowHi; ++y)
        for (int x = 0; x < w; x += 4) {
            const std::size_t at = static_cast<std::size_t>(y) * stride + static_cast<std::size_t>(x);
            const std::size_t pixel =
                static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x);
            const Int4 rgba =
                packRgba8(toBytes(load(r + at)), toBytes(load(g + at)), toBytes(load(b + at)), toBytes(load(a + at)));
            const std::size_t lanes = static_cast<std::size_t>(std::min(4, w - x));
            std::memcpy(&image_.rgba[pixel * 4], &rgba, lanes * 4);
            std::memcpy(&image_.depth[pixel], depth + at, lanes * sizeof(float));
        }
}

// The band's n projection buffers: count each pixel's splats, turn the
// counts into offsets, then write every LDI's stream in order, which leaves
// each pixel's entries grouped by LDI and back to front within each.
void LdiRenderer::fillBuffers(Band& band) {
    const std::size_t w = static_cast<std::size_t>(image_.width);
    const std::size_t p0 = static_cast<std::size_t>(band.reach0) * w, p1 = static_cast<std::size_t>(band.reach1) * w;
    // Count with a difference array: +1 where a row span starts, -1 after
    // it ends; one running sum then gives each pixel's count, a second its offset.
    band.start.assign(p1 - p0 + 1, 0);
    std::int32_t* diff = reinterpret_cast<std::int32_t*>(band.start.data()) - p0;
    for (std::size_t l = 0; l < set_.ldis.size(); ++l)
        for (std::uint32_t id : order_[l])
            rowSpans(id, band.reach0, band.reach1, [diff, w](int y, int xa, int xb, float) {
                const std::size_t row = static_cast<std::size_t>(y) * w;
                ++diff[row + static_cast<std::size_t>(xa)];
                --diff[row + static_cast<std::size_t>(xb) + 1];
            });
    std::int32_t count = 0;
    std::uint32_t offset = 0;
    for (std::size_t i = 0; i <= p1 - p0; ++i) {
        count += static_cast<std::int32_t>(band.start[i]);
        band.start[i] = offset;
        offset += static_cast<std::uint32_t>(count);
    }
    band.splats = offset;
    if (band.entries.size() < band.splats) band.entries.resize(band.splats);
    // Cursors: each pixel's start, advanced as entries land; shifted back after.
    std::uint32_t* cursor = band.start.data() - p0;
    Entry* entries = band.entries.data();
    for (std::size_t l = 0; l < set_.ldis.size(); ++l)
        for (std::uint32_t id : order_[l]) {
            const glm::u8vec4 c = items_->colors[id];
            const float a = items_->alphas[id], z = projected_[id].depth;
            footprint(id, band.reach0, band.reach1, [&](std::uint32_t pixel, float weight) {
                entries[cursor[pixel]++] = Entry{z, a * weight, c};
            });
        }
    for (std::size_t p = p1 - p0; p > 0; --p) band.start[p] = band.start[p - 1];
    band.start[0] = 0;
}

// Per pixel, the heads of its LDIs' runs are merged by depth, largest first.
void LdiRenderer::mergeBuffers(Band& band) {
    struct Run {
        std::uint32_t next, end;
    };
    std::vector<Run> runs;
    runs.reserve(set_.ldis.size());
    clearRowsOutsideReach(band);
    const std::size_t w = static_cast<std::size_t>(image_.width);
    const std::size_t p0 = static_cast<std::size_t>(band.reach0) * w, p1 = static_cast<std::size_t>(band.reach1) * w;
    const Entry* e = band.entries.data();
    for (std::size_t p = p0; p < p1; ++p) {
        const std::uint32_t begin = band.start[p - p0], end = band.start[p - p0 + 1];
        if (begin == end) {
            clearPixel(p);
            continue;
        }
        Accumulator acc;
        if (e[begin].colorLdi.w == e[end - 1].colorLdi.w) {
            // One LDI reaches this pixel: its run is already back to front.
            for (std::uint32_t k = begin; k < end; ++k) acc.over(e[k].colorLdi, e[k].alpha, e[k].depth);
        } else {
            runs.clear();
            std::uint32_t first = begin;
            for (std::uint32_t k = begin + 1; k <= end; ++k)
                if (k == end || e[k].colorLdi.w != e[k - 1].colorLdi.w) {
                    runs.push_back({first, k});
                    first = k;
                }
            while (runs.size() > 1) {
                std::size_t pick = 0;
                float deepest = e[runs[0].next].depth;
                for (std::size_t r = 1; r < runs.size(); ++r)
                    if (e[runs[r].next].depth > deepest) deepest = e[runs[r].next].depth, pick = r;
                const Entry& head = e[runs[pick].next];
                acc.over(head.colorLdi, head.alpha, head.depth);
                if (++runs[pick].next == runs[pick].end) {
                    runs[pick] = runs.back();
                    runs.pop_back();
                }
            }
            for (std::uint32_t k = runs[0].next; k < runs[0].end; ++k) acc.over(e[k].colorLdi, e[k].alpha, e[k].depth);
        }
        store(p, acc.color, acc.depth);
    }
}

inline void LdiRenderer::store(std::size_t p, Float4 color, float depth) {
    const Int4 v = toBytes(color);
    const std::int32_t rgba = packRgba8(v[0], v[1], v[2], v[3]);
    std::memcpy(&image_.rgba[p * 4], &rgba, sizeof rgba);
    image_.depth[p] = depth;
}

inline void LdiRenderer::clearPixel(std::size_t p) {
    std::uint8_t* out = &image_.rgba[p * 4];
    out[0] = out[1] = out[2] = out[3] = 0;
    image_.depth[p] = std::numeric_limits<float>::infinity();
}

// One frame in one parallel region: project, (order or sort), bands.
void LdiRenderer::frame(const View& view, bool depthSorted) {
    items_ = depthSorted ? &points_ : &slots_;
    const std::size_t n = items_->positions.size();
    image_.width = view.viewport.x;
    image_.height = view.viewport.y;
    const std::size_t pixels = static_cast<std::size_t>(image_.width) * static_cast<std::size_t>(image_.height);
    image_.rgba.resize(pixels * 4);
    image_.depth.resize(pixels);
    projected_.resize(n);
    const std::size_t ldis = set_.ldis.size();
    order_.resize(std::max<std::size_t>(order_.size(), depthSorted ? 1 : ldis));
    bands_.resize(static_cast<std::size_t>(threads_));
    const bool merge = !depthSorted && ldis > 1;
    if (depthSorted) {
        // The barrier's completion step must not throw: allocate here.
        byDepth_.reserve(n);
        order_[0].reserve(n);
    } else {
        for (std::size_t l = 0; l < ldis; ++l) order_[l].resize(set_.ldis[l].points.size());
    }

    auto afterProjection = [&]() noexcept {
        cutBands();
        if (!depthSorted) return;
        // The reference: every drawn point sorted by view depth, farthest first.
        const auto sortStart = std::chrono::steady_clock::now();
        byDepth_.clear();
        for (std::size_t i = 0; i < n; ++i)
            if (projected_[i].depth >= 0.0f) byDepth_.emplace_back(projected_[i].depth, static_cast<std::uint32_t>(i));
        std::sort(byDepth_.begin(), byDepth_.end(), std::greater<>());
        order_[0].clear();
        for (const auto& [z, id] : byDepth_) order_[0].push_back(id);
        orderMs_ = msSince(sortStart);
    };
    SpinBarrier projected(threads_), ordered(threads_);
    auto work = [&](std::size_t worker) {
        project(view, worker);
        projected.arriveAndWait(afterProjection);
        if (!depthSorted) {
            // Every worker leaves the barriers together: worker 0's clock
            // spans the whole phase.
            const auto orderStart = std::chrono::steady_clock::now();
            // Each worker walks its share of every LDI: one LDI's walk is cut
            // between the threads too.
            for (std::size_t l = 0; l < ldis; ++l)
                writeSlotsBackToFront(set_.ldis[l], view.eye, slotBase_[l], order_[l], worker, bands_.size());
            ordered.arriveAndWait();
            if (worker == 0) orderMs_ = msSince(orderStart);
        }
        Band& band = bands_[worker];
        if (merge) {
            fillBuffers(band);
            mergeBuffers(band);
        } else {
            compositeInOrder(band, order_[0]);
        }
    };
    pool_.run(work);
    splatCount_ = 0;
    for (const Band& b : bands_) splatCount_ += b.splats;
}

const PointImage& LdiRenderer::render(const View& view) {
    frame(view, false);
    return image_;
}

const PointImage& LdiRenderer::renderDepthSorted(const View& view) {
    frame(view, true);
    return image_;
}

}  // namespace arcomp
