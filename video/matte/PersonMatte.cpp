#include "video/matte/PersonMatte.hpp"

#include <opencv2/core.hpp>
#include <opencv2/core/hal/intrin.hpp>

#include <cstring>

namespace arcomp {

cv::Mat alphaOf(const cv::Mat& person) {
    cv::Mat alpha;
    cv::extractChannel(person, alpha, 3);
    return alpha;
}

namespace {

// (v * k + 127) / 255 without a division: exact for 8-bit inputs, and every
// step fits a 16-bit lane (v * k + 128 <= 65153), so the vectors below
// compute the same bytes.
std::uint8_t scaled(unsigned v, unsigned k) {
    const unsigned t = v * k + 128;
    return static_cast<std::uint8_t>((t + (t >> 8)) >> 8);
}

#if CV_SIMD
cv::v_uint16 scaled(const cv::v_uint16& v, const cv::v_uint16& k) {
    const cv::v_uint16 t = cv::v_mul_wrap(v, k) + cv::vx_setall_u16(128);
    return (t + (t >> 8)) >> 8;
}

cv::v_uint8 scaled(const cv::v_uint8& v, const cv::v_uint16& kLo, const cv::v_uint16& kHi) {
    cv::v_uint16 lo, hi;
    cv::v_expand(v, lo, hi);
    return cv::v_pack(scaled(lo, kLo), scaled(hi, kHi));
}
#endif

// The first column in [from, to) whose alpha is not 0, else `to`; and the
// end of the last one, else `from`. Eight columns a step: a person is a
// small part of most rows.
int firstNonZero(const std::uint8_t* a, int from, int to) {
    std::uint64_t word = 0;
    for (; from + 8 <= to; from += 8) {
        std::memcpy(&word, a + from, 8);
        if (word != 0) break;
    }
    while (from < to && a[from] == 0) ++from;
    return from;
}

int lastNonZeroEnd(const std::uint8_t* a, int from, int to) {
    std::uint64_t word = 0;
    for (; to - 8 >= from; to -= 8) {
        std::memcpy(&word, a + to - 8, 8);
        if (word != 0) break;
    }
    while (to > from && a[to - 1] == 0) --to;
    return to;
}

// Columns [from, to) of one row.
void premultiplyRow(const std::uint8_t* c, const std::uint8_t* a, std::uint8_t* o, int from, int to) {
    int x = from;
#if CV_SIMD
    for (; x + cv::v_uint8::nlanes <= to; x += cv::v_uint8::nlanes) {
        cv::v_uint8 b, g, r;
        cv::v_load_deinterleave(c + 3 * x, b, g, r);
        const cv::v_uint8 k = cv::vx_load(a + x);
        cv::v_uint16 kLo, kHi;
        cv::v_expand(k, kLo, kHi);
        cv::v_store_interleave(o + 4 * x, scaled(b, kLo, kHi), scaled(g, kLo, kHi), scaled(r, kLo, kHi), k);
    }
#endif
    for (; x < to; ++x) {
        const unsigned k = a[x];
        o[4 * x + 0] = scaled(c[3 * x + 0], k);
        o[4 * x + 1] = scaled(c[3 * x + 1], k);
        o[4 * x + 2] = scaled(c[3 * x + 2], k);
        o[4 * x + 3] = static_cast<std::uint8_t>(k);
    }
}

}  // namespace

void premultiply(const cv::Mat& frame, const cv::Mat& alpha, cv::Mat& person) {
    CV_Assert(frame.type() == CV_8UC3 && alpha.type() == CV_8UC1 && frame.size() == alpha.size());
    person.create(frame.size(), CV_8UC4);
    cv::parallel_for_(cv::Range(0, frame.rows), [&](const cv::Range& rows) {
        for (int y = rows.start; y < rows.end; ++y) {
            const std::uint8_t* a = alpha.ptr<std::uint8_t>(y);
            std::uint8_t* o = person.ptr<std::uint8_t>(y);
            // A person covers a fraction of the frame: where alpha is 0 the
            // layer is 0, written as such rather than multiplied out.
            const int from = firstNonZero(a, 0, alpha.cols), to = lastNonZeroEnd(a, from, alpha.cols);
            std::memset(o, 0, 4 * static_cast<std::size_t>(from));
            std::memset(o + 4 * to, 0, 4 * static_cast<std::size_t>(alpha.cols - to));
            premultiplyRow(frame.ptr<std::uint8_t>(y), a, o, from, to);
        }
    });
}

}  // namespace arcomp
