#include "graph/points/McMillanOrder.hpp"
#include "graph/core/Check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace arcomp {

namespace {

EpipoleSide sideOf(float v, int size) {
    if (v < 0.0f) return EpipoleSide::Before;
    if (v >= static_cast<float>(size)) return EpipoleSide::After;
    return EpipoleSide::Inside;
}

// One axis's scan: the cells before the epipole's cell, then the rest, each
// towards or away from it.
struct AxisRun {
    int first, last, step;  // inclusive; empty when (last - first) * step < 0
};

void axisRuns(float epipole, int size, bool towards, AxisRun runs[2]) {
    const int split = static_cast<int>(std::clamp(std::floor(epipole), 0.0f, static_cast<float>(size)));
    // Cells [0, split) lie before p: towards p means ascending.
    runs[0] = towards ? AxisRun{0, split - 1, 1} : AxisRun{split - 1, 0, -1};
    runs[1] = towards ? AxisRun{size - 1, split, -1} : AxisRun{split, size - 1, 1};
}

bool emptyRun(const AxisRun& r) { return (r.last - r.first) * r.step < 0; }

}  // namespace

Epipole epipoleOf(const LdiCamera& camera, const glm::vec3& eye) {
    const glm::vec3 c = camera.toCamera(eye);
    Epipole e;
    const float length = glm::length(c);
    if (length == 0.0f) {
        // Same eye: every order across pixels is right; scan away from the centre.
        e.pixel = camera.principal();
    } else if (std::abs(c.z) <= 1e-7f * length) {
        // On e0's screen plane: the epipole is at infinity in direction (x, y).
        // Scanning towards it from in front equals scanning away from its
        // mirror from behind, so either sign gives the same order.
        e.pixel = camera.principal() + glm::vec2(c.x, c.y) / length * 1e9f;
        e.inFront = true;
    } else {
        e.pixel = glm::vec2(c.x, c.y) / c.z * camera.focal + camera.principal();
        e.inFront = c.z > 0.0f;
    }
    e.column = sideOf(e.pixel.x, camera.width);
    e.row = sideOf(e.pixel.y, camera.height);
    return e;
}

namespace {

// The walk itself, or one of `parts` pieces of it: put(position, k)
// receives each LDI slot k (an index into ldi.points) with its position in
// the whole walk's output. The walk runs row by row through the sheets, and
// a row's points fill a known stretch of the output (pixelStart gives their
// count), so each piece can find its rows alone: those starting within its
// equal share of the positions.
template <class Put>
void walkBackToFront(const Ldi& ldi, const glm::vec3& eye, std::size_t part, std::size_t parts, Put&& put) {
    const LdiCamera& cam = ldi.camera;
    const Epipole e = epipoleOf(cam, eye);
    AxisRun columns[2], rows[2];
    axisRuns(e.pixel.x, cam.width, e.inFront, columns);
    axisRuns(e.pixel.y, cam.height, e.inFront, rows);
    // The place on pixel (x, y)'s ray nearest to e1 lies at depth
    // dot(e1 - e0, ray direction), and in e0's camera axes the ray runs along
    // (lx, ly, 1) / |(lx, ly, 1)|: one square root a pixel, no rotation.
    const glm::vec3 offset = cam.toCamera(eye);
    const glm::vec2 principal = cam.principal();
    const std::size_t total = ldi.points.size();
    const std::size_t from = total * part / parts, to = total * (part + 1) / parts;
    std::size_t position = 0;  // of the current row's first point in the whole walk
    for (const AxisRun& rs : rows) {
        if (emptyRun(rs)) continue;
        for (const AxisRun& cs : columns) {
            if (emptyRun(cs)) continue;
            const auto lowColumn = static_cast<std::uint32_t>(std::min(cs.first, cs.last));
            const auto highColumn = static_cast<std::uint32_t>(std::max(cs.first, cs.last));
            for (int y = rs.first;; y += rs.step) {
                if (position >= to) return;
                const std::uint32_t rowBase = static_cast<std::uint32_t>(y) * static_cast<std::uint32_t>(cam.width);
                const std::size_t count =
                    ldi.pixelStart[rowBase + highColumn + 1] - ldi.pixelStart[rowBase + lowColumn];
                if (position >= from && count > 0) {
                    std::size_t next = position;
                    const float ly = (static_cast<float>(y) + 0.5f - principal.y) / cam.focal;
                    const float rowOffset = offset.y * ly + offset.z, rowLength2 = ly * ly + 1.0f;
                    for (int x = cs.first;; x += cs.step) {
                        const std::uint32_t pixel = rowBase + static_cast<std::uint32_t>(x);
                        const std::uint32_t begin = ldi.pixelStart[pixel], end = ldi.pixelStart[pixel + 1];
                        if (begin != end) {
                            const float lx = (static_cast<float>(x) + 0.5f - principal.x) / cam.focal;
                            const float nearest = (offset.x * lx + rowOffset) / std::sqrt(lx * lx + rowLength2);
                            // Points before `nearest` along the ray, ascending, meet those
                            // after it, descending; the farther from it goes first.
                            std::uint32_t lo = begin, hi = end;
                            std::uint32_t split = static_cast<std::uint32_t>(
                                std::upper_bound(ldi.rayDepth.begin() + begin, ldi.rayDepth.begin() + end, nearest) -
                                ldi.rayDepth.begin());
                            while (lo < split && hi > split) {
                                if (nearest - ldi.rayDepth[lo] >= ldi.rayDepth[hi - 1] - nearest)
                                    put(next++, lo++);
                                else
                                    put(next++, --hi);
                            }
                            while (lo < split) put(next++, lo++);
                            while (hi > split) put(next++, --hi);
                        }
                        if (x == cs.last) break;
                    }
                }
                position += count;
                if (y == rs.last) break;
            }
        }
    }
}

}  // namespace

void appendBackToFront(const Ldi& ldi, const glm::vec3& eye, std::vector<std::uint32_t>& out) {
    const std::size_t at = out.size();
    out.resize(at + ldi.points.size());
    walkBackToFront(ldi, eye, 0, 1, [&](std::size_t i, std::uint32_t k) { out[at + i] = ldi.points[k]; });
}

void writeSlotsBackToFront(const Ldi& ldi, const glm::vec3& eye, std::uint32_t base, std::span<std::uint32_t> slots,
                           std::size_t part, std::size_t parts) {
    ARCOMP_CHECK(slots.size() == ldi.points.size() && part < parts,
                 "one slot per point, a piece of the walk that exists");
    walkBackToFront(ldi, eye, part, parts, [&](std::size_t i, std::uint32_t k) { slots[i] = base + k; });
}

}  // namespace arcomp
