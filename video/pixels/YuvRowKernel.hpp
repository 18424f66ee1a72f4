#pragma once
// The vector part of YUV to BGR, internal to video/YuvConversion*.cpp. It is
// built twice: for the SSE2 baseline the library targets and, on x86-64, for
// AVX2, which the caller picks at run time as cvtColor does. Only OpenCV's
// universal intrinsics see the compile flags, so each build gets the widest
// vectors its flags allow. The including file names the namespace the build
// goes in, keeping the two apart at link time:
//
//   #define ARCOMP_YUV_KERNEL_NAMESPACE avx2
//   #include "video/pixels/YuvRowKernel.hpp"

#include <opencv2/core/hal/intrin.hpp>

#include <cstdint>

#ifndef ARCOMP_YUV_KERNEL_NAMESPACE
#error "define ARCOMP_YUV_KERNEL_NAMESPACE before including video/pixels/YuvRowKernel.hpp"
#endif

namespace arcomp::yuv {

// The conversion constants sized for 16-bit SIMD lanes, so one vector holds 8
// (SSE) or 16 (AVX2) pixels instead of half that in 32-bit lanes. Samples
// enter as the high byte of a 16-bit word and each product keeps its high 16
// bits (one multiply-high instruction); with coefficients in 1/8192 that
// leaves every term in 1/32 of an output level. The worst sum, bright Y plus
// BT.709 limited-range blue, stays near 17,500 of int16's 32,767, so no step
// saturates. Truncated products and rounded coefficients stay within 0.15 of
// a level of exact arithmetic: the output matches the former 16.16
// fixed-point code or differs from it by one.
constexpr int kFracBits = 5;

struct FixedYuvToRgb {
    std::uint16_t a;              // times Y << 8, unsigned: Y reaches 255
    std::int16_t bu, gu, gv, rv;  // times (C - 128) << 8; green's negated
    std::int16_t bias;            // -a y0, plus half a level so the final shift rounds
};

// One build's row converters. Each converts the whole vectors at the start of
// a row and returns how many columns they covered; the caller converts the
// rest in scalar code that matches the vectors bit for bit.
using YuyvRowVectors = int (*)(const std::uint8_t* in, std::uint8_t* out, int width, const FixedYuvToRgb& k);
using Nv12RowVectors = int (*)(const std::uint8_t* y, const std::uint8_t* uv, std::uint8_t* out, int width,
                               const FixedYuvToRgb& k);

struct RowKernels {
    YuyvRowVectors yuyv;
    Nv12RowVectors nv12;
};

#if defined(__x86_64__)
// The AVX2 build (video/pixels/YuvConversionAvx2.cpp); call it only where the CPU has AVX2.
RowKernels avx2RowKernels();
#endif

namespace ARCOMP_YUV_KERNEL_NAMESPACE {

#if CV_SIMD
// The vector conversion of 2 * nlanes pixels: the luma of the even and the
// odd pixels and the chroma each pair shares, which is how both YUYV and NV12
// rows deinterleave.
struct VectorKernel {
    static constexpr int kPixels = 2 * cv::v_uint8::nlanes;

    explicit VectorKernel(const FixedYuvToRgb& k)
        : a(cv::vx_setall_u16(k.a)), bu(cv::vx_setall_s16(k.bu)), gu(cv::vx_setall_s16(k.gu)),
          gv(cv::vx_setall_s16(k.gv)), rv(cv::vx_setall_s16(k.rv)), bias(cv::vx_setall_s16(k.bias)) {}

    // Inlined by force: as a call it spills the coefficient vectors and costs 5%.
    CV_ALWAYS_INLINE void convert(const cv::v_uint8& yEven, const cv::v_uint8& yOdd, const cv::v_uint8& u,
                                  const cv::v_uint8& v, std::uint8_t* out) const {
        cv::v_int16 uLo, uHi, vLo, vHi;
        centredHigh(u, uLo, uHi);
        centredHigh(v, vLo, vHi);
        const cv::v_int16 bLo = bias + cv::v_mul_hi(uLo, bu), bHi = bias + cv::v_mul_hi(uHi, bu);
        const cv::v_int16 rLo = bias + cv::v_mul_hi(vLo, rv), rHi = bias + cv::v_mul_hi(vHi, rv);
        const cv::v_int16 gLo = bias + cv::v_mul_hi(uLo, gu) + cv::v_mul_hi(vLo, gv);
        const cv::v_int16 gHi = bias + cv::v_mul_hi(uHi, gu) + cv::v_mul_hi(vHi, gv);
        cv::v_int16 eLo, eHi, oLo, oHi;
        luma(yEven, eLo, eHi);
        luma(yOdd, oLo, oHi);
        // A pair's six bytes B G R B G R as three 16-bit words, so that the
        // final interleave moves words: that costs SSE2, which lacks a byte
        // shuffle, about half of what interleaving three byte planes does.
        cv::v_uint8 bg0, bg1, rb0, rb1, gr0, gr1;
        cv::v_zip(level(eLo, eHi, bLo, bHi), level(eLo, eHi, gLo, gHi), bg0, bg1);
        cv::v_zip(level(eLo, eHi, rLo, rHi), level(oLo, oHi, bLo, bHi), rb0, rb1);
        cv::v_zip(level(oLo, oHi, gLo, gHi), level(oLo, oHi, rLo, rHi), gr0, gr1);
        storeWords(out, bg0, rb0, gr0);
        storeWords(out + 3 * cv::v_uint8::nlanes, bg1, rb1, gr1);
    }

private:
    // (C - 128) << 8 as int16: flipping the top bit recentres the byte, and
    // zipping it behind a zero byte puts it in the high half of each
    // (little-endian) word.
    static void centredHigh(const cv::v_uint8& c, cv::v_int16& lo, cv::v_int16& hi) {
        cv::v_uint8 l, h;
        cv::v_zip(cv::vx_setzero_u8(), c ^ cv::vx_setall_u8(128), l, h);
        lo = cv::v_reinterpret_as_s16(l);
        hi = cv::v_reinterpret_as_s16(h);
    }

    void luma(const cv::v_uint8& y, cv::v_int16& lo, cv::v_int16& hi) const {
        cv::v_uint8 l, h;
        cv::v_zip(cv::vx_setzero_u8(), y, l, h);
        lo = cv::v_reinterpret_as_s16(cv::v_mul_hi(cv::v_reinterpret_as_u16(l), a));
        hi = cv::v_reinterpret_as_s16(cv::v_mul_hi(cv::v_reinterpret_as_u16(h), a));
    }

    static void storeWords(std::uint8_t* out, const cv::v_uint8& a, const cv::v_uint8& b, const cv::v_uint8& c) {
        cv::v_store_interleave(reinterpret_cast<std::uint16_t*>(out), cv::v_reinterpret_as_u16(a),
                               cv::v_reinterpret_as_u16(b), cv::v_reinterpret_as_u16(c));
    }

    // The saturating pack is the clamp to 0..255.
    static cv::v_uint8 level(const cv::v_int16& lLo, const cv::v_int16& lHi, const cv::v_int16& cLo,
                             const cv::v_int16& cHi) {
        return cv::v_pack_u((lLo + cLo) >> kFracBits, (lHi + cHi) >> kFracBits);
    }

    cv::v_uint16 a;
    cv::v_int16 bu, gu, gv, rv, bias;
};
#endif

inline int yuyvRowVectors(const std::uint8_t* in, std::uint8_t* out, int width, const FixedYuvToRgb& k) {
    int x = 0;
#if CV_SIMD
    const VectorKernel kernel(k);
    for (; x + VectorKernel::kPixels <= width; x += VectorKernel::kPixels) {
        cv::v_uint8 y0, u, y1, v;
        cv::v_load_deinterleave(in + 2 * x, y0, u, y1, v);
        kernel.convert(y0, y1, u, v, out + 3 * x);
    }
#endif
    return x;
}

inline int nv12RowVectors(const std::uint8_t* y, const std::uint8_t* uv, std::uint8_t* out, int width,
                          const FixedYuvToRgb& k) {
    int x = 0;
#if CV_SIMD
    const VectorKernel kernel(k);
    for (; x + VectorKernel::kPixels <= width; x += VectorKernel::kPixels) {
        cv::v_uint8 yEven, yOdd, u, v;
        cv::v_load_deinterleave(y + x, yEven, yOdd);
        cv::v_load_deinterleave(uv + x, u, v);
        kernel.convert(yEven, yOdd, u, v, out + 3 * x);
    }
#endif
    return x;
}

inline RowKernels rowKernels() { return {&yuyvRowVectors, &nv12RowVectors}; }

}  // namespace ARCOMP_YUV_KERNEL_NAMESPACE

}  // namespace arcomp::yuv
