#include "video/pixels/AreaShrink.hpp"

#include <opencv2/core.hpp>
#include <opencv2/core/hal/intrin.hpp>
#include <opencv2/imgproc.hpp>

#include <cstdint>
#include <vector>

namespace arcomp {

namespace {

// sum / 16 rounded to nearest, ties to even: OpenCV's saturate_cast of the
// float sum times 1/16, in integers.
std::uint16_t sixteenth(unsigned sum) { return static_cast<std::uint16_t>((sum + 7 + ((sum >> 4) & 1u)) >> 4); }

#if CV_SIMD
cv::v_uint16 sixteenth(const cv::v_uint16& sum) {
    return (sum + cv::vx_setall_u16(7) + ((sum >> 4) & cv::vx_setall_u16(1))) >> 4;
}
#endif

// One output row from four input rows of `samples` bytes (BGR interleaved).
// Columns first: the four rows' sum per sample. Then, at every sample, the
// rounded mean of it and the three samples of its channel to its right; an
// output pixel takes the values at the start of its block of four pixels.
// The second step computes four times the values it keeps, as plain vector
// adds: cheaper than shuffling channels apart.
void shrinkRow(const std::uint8_t* const rows[4], int samples, std::vector<std::uint16_t>& columns,
               std::vector<std::uint16_t>& means, std::uint8_t* out) {
    std::uint16_t* s = columns.data();
    int x = 0;
#if CV_SIMD
    for (; x + cv::v_uint8::nlanes <= samples; x += cv::v_uint8::nlanes) {
        cv::v_uint16 lo[4], hi[4];
        for (int r = 0; r < 4; ++r) cv::v_expand(cv::vx_load(rows[r] + x), lo[r], hi[r]);
        cv::v_store(s + x, lo[0] + lo[1] + lo[2] + lo[3]);
        cv::v_store(s + x + cv::v_uint16::nlanes, hi[0] + hi[1] + hi[2] + hi[3]);
    }
#endif
    for (; x < samples; ++x) s[x] = static_cast<std::uint16_t>(rows[0][x] + rows[1][x] + rows[2][x] + rows[3][x]);

    // The last block starts at samples - 12 and needs sums up to samples - 1.
    const int last = samples - 9;
    std::uint16_t* m = means.data();
    x = 0;
#if CV_SIMD
    for (; x + cv::v_uint16::nlanes <= last; x += cv::v_uint16::nlanes)
        cv::v_store(m + x, sixteenth(cv::vx_load(s + x) + cv::vx_load(s + x + 3) + cv::vx_load(s + x + 6) +
                                     cv::vx_load(s + x + 9)));
#endif
    for (; x < last; ++x) m[x] = sixteenth(s[x] + s[x + 3] + s[x + 6] + s[x + 9]);
    for (int o = 0, i = 0; i < last; o += 3, i += 12) {
        out[o] = static_cast<std::uint8_t>(m[i]);
        out[o + 1] = static_cast<std::uint8_t>(m[i + 1]);
        out[o + 2] = static_cast<std::uint8_t>(m[i + 2]);
    }
}

}  // namespace

void shrinkByArea(const cv::Mat& frame, double scale, cv::Mat& small) {
    if (scale != 0.25 || frame.type() != CV_8UC3 || frame.cols % 4 != 0 || frame.rows % 4 != 0 || frame.empty()) {
        cv::resize(frame, small, {}, scale, scale, cv::INTER_AREA);
        return;
    }
    small.create(frame.rows / 4, frame.cols / 4, CV_8UC3);
    const int samples = frame.cols * 3;
    cv::parallel_for_(cv::Range(0, small.rows), [&](const cv::Range& range) {
        std::vector<std::uint16_t> columns(static_cast<std::size_t>(samples)), means(static_cast<std::size_t>(samples));
        for (int y = range.start; y < range.end; ++y) {
            const std::uint8_t* const rows[4] = {frame.ptr<std::uint8_t>(4 * y), frame.ptr<std::uint8_t>(4 * y + 1),
                                                 frame.ptr<std::uint8_t>(4 * y + 2),
                                                 frame.ptr<std::uint8_t>(4 * y + 3)};
            shrinkRow(rows, samples, columns, means, small.ptr<std::uint8_t>(y));
        }
    });
}

}  // namespace arcomp
