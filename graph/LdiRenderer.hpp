#pragma once
// Draws an LdiSet for any eye on the CPU, the paper's way: each LDI's
// points in McMillan order are splatted into that LDI's projection buffer
// (output resolution, per pixel the point ids back to front); then per
// output pixel the n buffers' heads are merged by depth, largest first,
// and composited with "over". The result is an image the renderer uploads
// as a texture, with a depth to test against the CG.
//
//   LdiRenderer r(set);
//   const PointImage& img = r.render(view);             // McMillan + merge
//   const PointImage& ref = r.renderDepthSorted(view);  // exact order, same splats
//
// Splat footprint: a disc of half a voxel face's diagonal on screen (at least
// 0.71 px, so that every point reaches a pixel centre), weighted with a
// quadratic falloff from 1 at the centre to 0.4 at its rim.
//
// Layout: the n projection buffers are stored interleaved, not side by
// side: for each output pixel, LDI 0's entries, then LDI 1's, ... each run
// already back to front. An entry carries the point's depth, weighted alpha
// and colour instead of its id, so the merge never reads the point arrays.
// It is the same data, but one stable counting sort builds it and the merge
// reads it from one place.
//
// With one LDI (and for the depth-sorted reference) there is one stream,
// already back to front, so its splats are composited as they come and
// the buffers are skipped: the merge of a single buffer is the identity.
//
// Two threads: LDIs are ordered and splatted in parallel, and the merge
// (or the single stream's compositing) splits the image's rows. The
// renderer keeps its buffers between frames, so it allocates nothing once
// warm; one renderer serves one caller thread.

#include "graph/Ldi.hpp"
#include "graph/View.hpp"

#include <glm/gtc/type_precision.hpp>

#include <cstdint>
#include <limits>
#include <vector>

namespace arcomp {

struct PointImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  // premultiplied RGBA8, rows top to bottom
    std::vector<float> depth;        // view-axis depth of the nearest point drawn there; +inf where none
    std::size_t coveredPixels() const;
};

class LdiRenderer {
public:
    explicit LdiRenderer(const LdiSet& set, int threads = 2);

    const PointImage& render(const View& view);
    const PointImage& renderDepthSorted(const View& view);

    // Splats written in the last frame (all buffers together).
    std::size_t lastSplatCount() const { return splatCount_; }

private:
    // What the merge needs of one splat, packed so that it reads the
    // projection buffers front to back without touching the points.
    struct Entry {
        float depth;          // view-axis depth of the point
        float alpha;          // the point's alpha times the footprint weight
        glm::u8vec4 colorLdi; // straight RGB8, and the LDI it came from in .w
    };
    struct Splat {
        std::uint32_t pixel;
        Entry entry;
    };
    struct Accumulator {
        glm::vec3 color{0.0f};  // premultiplied
        float alpha = 0.0f;
        float depth = std::numeric_limits<float>::infinity();
        // Porter-Duff "over", back to front, on premultiplied colour.
        void over(glm::u8vec4 straightRgb, float a, float z) {
            color = glm::vec3(straightRgb) * (a * (1.0f / 255.0f)) + color * (1.0f - a);
            alpha = a + alpha * (1.0f - a);
            depth = z < depth ? z : depth;
        }
    };

    void project(const View& view);
    void splat(const std::vector<std::uint32_t>& ids, std::size_t begin, std::size_t end, std::uint8_t ldi,
               std::vector<Splat>& out) const;
    template <class Emit> void footprint(std::uint32_t id, std::uint8_t ldi, int rowLo, int rowHi, Emit&& emit) const;
    void compositeInOrder(const std::vector<std::uint32_t>& ids);
    void store(std::size_t pixel, const Accumulator& acc);
    void gather(std::size_t streams);
    void composite(bool merge);
    void compositeRows(int y0, int y1, bool merge);
    template <class F> void parallel(F&& f);

    const LdiSet& set_;
    int threads_;
    PointImage image_;
    // Per frame, per point: screen position, view depth, footprint radius.
    std::vector<glm::vec2> screen_;
    std::vector<float> depth_, radius_;
    std::vector<std::vector<std::uint32_t>> order_;   // per LDI (or half of the reference), back to front
    std::vector<std::vector<Splat>> splats_;          // per stream, in drawing order
    std::vector<std::uint32_t> pixelStart_;
    std::vector<Entry> sorted_;
    std::vector<std::pair<float, std::uint32_t>> byDepth_;
    std::vector<Accumulator> accumulators_;
    std::size_t splatCount_ = 0;
};

} // namespace arcomp
