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
// Layout: the image is cut into one band of rows per thread, the cut
// placed so that each band gets about the same number of splats (from a
// histogram of the projected points). Within its band a thread owns the n
// projection buffers, stored interleaved: per output pixel, LDI 0's entries,
// then LDI 1's, ... each run already back to front. They are filled in two
// passes over the LDIs' McMillan streams, one counting each pixel's splats
// (per footprint row, into a difference array) and one writing them in
// place, instead of writing a list of splats and sorting it by pixel. The
// points are kept in LDI slot order, so the McMillan walk reads their
// projections almost sequentially. An entry carries
// the point's depth, weighted alpha and colour instead of its id, so the
// merge never reads the point arrays. A pixel whose entries all come from
// one LDI is composited straight through: its merge is the identity.
//
// With one LDI (and for the depth-sorted reference) there is one stream,
// already back to front, so its splats are composited as they come and
// the buffers are skipped; colour and depth then lie in planes, and each
// splat is composited four pixels of a row at a time.
//
// Two threads by default: each frame is one parallel region (projection,
// then McMillan order, each LDI's walk cut between the threads, then the bands).
// The renderer keeps its buffers between frames, so it allocates nothing
// once warm; one renderer serves one caller thread. It copies the cloud's
// positions and colours once, when constructed (the point size is read
// every frame).

#include "graph/core/View.hpp"
#include "graph/points/Ldi.hpp"
#include "graph/points/WorkerPool.hpp"

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
    // Four floats in one SIMD register (SSE on x86-64, NEON on Arm), by the
    // compiler's vector extension: one splat's "over" is then three vector
    // operations instead of a dozen scalar ones.
    using Float4 = float __attribute__((vector_size(16)));

    explicit LdiRenderer(const LdiSet& set, int threads = 2);

    const PointImage& render(const View& view);
    const PointImage& renderDepthSorted(const View& view);

    // Splats written in the last frame (all buffers together).
    std::size_t lastSplatCount() const { return splatCount_; }
    // Wall milliseconds the last frame spent putting its points in back-to-
    // front order: the McMillan walks, or the reference's sort.
    double lastOrderMs() const { return orderMs_; }

private:
    // What the merge needs of one splat, packed so that it reads the
    // projection buffers front to back without touching the points.
    struct Entry {
        float depth;           // view-axis depth of the point
        float alpha;           // the point's alpha times the footprint weight
        glm::u8vec4 colorLdi;  // straight RGB8, and the LDI it came from in .w
    };
    struct Accumulator {
        Float4 color{0.0f, 0.0f, 0.0f, 0.0f};  // premultiplied RGB, alpha in [3]
        float depth = std::numeric_limits<float>::infinity();
        // Porter-Duff "over", back to front, on premultiplied colour.
        void over(Float4 premultiplied, float z) {
            color = premultiplied + color * (1.0f - premultiplied[3]);
            depth = z < depth ? z : depth;
        }
        void over(glm::u8vec4 straightRgb, float a, float z) { over(premultiply(straightRgb, a), z); }
        static Float4 premultiply(glm::u8vec4 straightRgb, float a) {
            const float k = a * (1.0f / 255.0f);
            return Float4{straightRgb.r * k, straightRgb.g * k, straightRgb.b * k, a};
        }
    };
    // One thread's rows and its share of the projection buffers.
    struct Band {
        int y0 = 0, y1 = 0;
        int reach0 = 0, reach1 = 0;        // rows of the band any splat reaches (projection: of its points)
        std::vector<std::uint32_t> start;  // per pixel of the band, + 1: offsets into entries
        std::vector<Entry> entries;
        // Single-stream path: premultiplied R, G, B, A and depth, one plane
        // each, rows kPlanePad wider than the image (see compositeInOrder).
        std::vector<float> planes;
        std::vector<float> rowWeight;  // projection's histogram, per image row
        std::size_t splats = 0;
    };
    enum class Streams { Single, Merged };

    void frame(const View& view, bool depthSorted);
    void project(const View& view, std::size_t worker);
    void cutBands();
    struct PixelBox {
        int x0, x1, y0, y1;  // inclusive
    };
    bool reach(std::uint32_t id, int rowLo, int rowHi, PixelBox& box) const;
    template <class Span>
    void rowSpans(std::uint32_t id, int rowLo, int rowHi, Span&& span) const;
    template <class Emit>
    void footprint(std::uint32_t id, int rowLo, int rowHi, Emit&& emit) const;
    void compositeInOrder(Band& band, const std::vector<std::uint32_t>& ids);
    void fillBuffers(Band& band);
    void mergeBuffers(Band& band);
    void store(std::size_t pixel, Float4 color, float depth);
    static constexpr int kPlanePad = 3;
    void clearPixel(std::size_t pixel);
    void clearRowsOutsideReach(const Band& band);

    const LdiSet& set_;
    int threads_;
    WorkerPool pool_;  // started once: a frame wakes its threads
    PointImage image_;
    // What is drawn, converted once: the points in LDI slot order (LDI 0's
    // ldi.points, then LDI 1's, ...), so that a McMillan walk reads them
    // almost sequentially, and in id order for the depth-sorted reference.
    // Colours are straight RGB8 with the LDI in .w, for the projection
    // buffers, and premultiplied floats, for the single stream.
    struct Items {
        std::vector<glm::vec3> positions;
        std::vector<glm::u8vec4> colors;
        std::vector<float> alphas;
        std::vector<Float4> premultiplied;
    };
    Items slots_, points_;
    std::vector<std::uint32_t> slotBase_;  // per LDI, its first slot
    const Items* items_ = nullptr;         // this frame's
    // Per frame, per item: screen position, view depth (< 0: not drawn), footprint radius.
    struct Projected {
        glm::vec2 screen;
        float depth;
        float radius;
    };
    std::vector<Projected> projected_;
    std::vector<std::vector<std::uint32_t>> order_;  // items back to front, per LDI (the reference: one)
    std::vector<std::pair<float, std::uint32_t>> byDepth_;
    std::vector<Band> bands_;
    std::size_t splatCount_ = 0;
    double orderMs_ = 0.0;
};

}  // namespace arcomp
