#include "video/pixels/YuvConversion.hpp"

#define ARCOMP_YUV_KERNEL_NAMESPACE baseline
#include "video/pixels/YuvRowKernel.hpp"

#include <opencv2/core/utility.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace arcomp {

namespace {

using yuv::FixedYuvToRgb;
using yuv::kFracBits;

struct LumaWeights {
    double kr;
    double kb;
};

// ITU-R BT.601 and BT.709: luma weights of R and B (G takes the rest).
LumaWeights lumaWeights(YuvMatrix m) {
    return m == YuvMatrix::Bt709 ? LumaWeights{0.2126, 0.0722} : LumaWeights{0.299, 0.114};
}

// Per-encoding constants for R = a(Y - y0) + rv V', G = a(Y - y0) - gu U' - gv V',
// B = a(Y - y0) + bu U' with U' = U - 128, V' = V - 128.
struct YuvToRgb {
    double y0;
    double a, rv, gu, gv, bu;
};

YuvToRgb yuvToRgb(YuvEncoding e) {
    const auto [kr, kb] = lumaWeights(e.matrix);
    const double kg = 1.0 - kr - kb;
    const bool limited = e.range == YuvRange::Limited;
    const double ys = limited ? 255.0 / 219.0 : 1.0;
    const double cs = limited ? 255.0 / 224.0 : 1.0;
    const double rv = 2.0 * (1.0 - kr) * cs;
    const double bu = 2.0 * (1.0 - kb) * cs;
    return {limited ? 16.0 : 0.0, ys, rv, bu * kb / kg, rv * kr / kg, bu};
}

FixedYuvToRgb fixedYuvToRgb(YuvEncoding e) {
    const YuvToRgb k = yuvToRgb(e);
    auto q13 = [](double v) { return static_cast<std::int16_t>(std::lround(v * 8192.0)); };
    const double scale = 1 << kFracBits;
    // Green's coefficients go in negated so that all three channels add
    // products truncated the same way, down; subtracting them would round
    // green up instead and miss the exact result twice as often.
    return {static_cast<std::uint16_t>(std::lround(k.a * 8192.0)),
            q13(k.bu),
            q13(-k.gu),
            q13(-k.gv),
            q13(k.rv),
            static_cast<std::int16_t>(std::lround(scale / 2 - k.a * k.y0 * scale))};
}

// Scalar twins of the vector steps (video/pixels/YuvRowKernel.hpp), bit for bit, for
// the columns left over after the last full vector: a frame's result must not
// depend on where its width happens to cut the vectors, nor on which build of
// the kernel the CPU runs.
inline int lumaTerm(const FixedYuvToRgb& k, int y) { return (y << 8) * k.a >> 16; }
inline int chromaTerm(std::int16_t coefficient, int c) { return ((c - 128) << 8) * coefficient >> 16; }

struct ChromaTerms {
    int b, g, r;  // bias included: shared by the pixels that share the chroma sample
};

inline ChromaTerms chromaTerms(const FixedYuvToRgb& k, int u, int v) {
    return {k.bias + chromaTerm(k.bu, u), k.bias + chromaTerm(k.gu, u) + chromaTerm(k.gv, v),
            k.bias + chromaTerm(k.rv, v)};
}

inline std::uint8_t toLevel(int fixed) { return static_cast<std::uint8_t>(std::clamp(fixed >> kFracBits, 0, 255)); }

inline void putBgr(std::uint8_t* out, const FixedYuvToRgb& k, const ChromaTerms& c, int y) {
    const int l = lumaTerm(k, y);
    out[0] = toLevel(l + c.b);
    out[1] = toLevel(l + c.g);
    out[2] = toLevel(l + c.r);
}

// The build of the vector kernel for the widest instructions this CPU has,
// chosen once. The library targets SSE2, but cvtColor, which the bench holds
// us to, picks AVX2 at run time: twice the pixels per instruction.
yuv::RowKernels widestRowKernels() {
#if defined(__x86_64__)
    __builtin_cpu_init();  // a conversion might run from a static initialiser, before libgcc's has
    if (__builtin_cpu_supports("avx2")) return yuv::avx2RowKernels();
#endif
    return yuv::baseline::rowKernels();
}

const yuv::RowKernels& rowKernels() {
    static const yuv::RowKernels kernels = widestRowKernels();
    return kernels;
}

void yuyvRowToBgr(const std::uint8_t* in, std::uint8_t* out, int width, const FixedYuvToRgb& k,
                  yuv::YuyvRowVectors vectors) {
    int x = vectors(in, out, width, k);
    // An odd last column has no V of its own and is left as it always was.
    for (; x + 1 < width; x += 2) {
        const std::uint8_t* p = in + 2 * x;
        const ChromaTerms c = chromaTerms(k, p[1], p[3]);
        putBgr(out + 3 * x, k, c, p[0]);
        putBgr(out + 3 * x + 3, k, c, p[2]);
    }
}

void nv12RowToBgr(const std::uint8_t* y, const std::uint8_t* uv, std::uint8_t* out, int width, const FixedYuvToRgb& k,
                  yuv::Nv12RowVectors vectors) {
    int x = vectors(y, uv, out, width, k);
    for (; x < width; ++x) putBgr(out + 3 * x, k, chromaTerms(k, uv[x & ~1], uv[(x & ~1) + 1]), y[x]);
}

// Stripes of about 64k pixels, as cvtColor cuts them: enough for the pool to
// balance its threads, few enough that scheduling stays out of the profile.
double stripes(int width, int height) { return std::max(1.0, static_cast<double>(width) * height / (1 << 16)); }

struct YuvPixel {
    double y, u, v;  // u, v centred on 128
};

YuvPixel bgrToYuvPixel(const YuvEncoding& e, const cv::Vec3b& p) {
    const auto [kr, kb] = lumaWeights(e.matrix);
    const double r = p[2] / 255.0, g = p[1] / 255.0, b = p[0] / 255.0;
    const double y = kr * r + (1.0 - kr - kb) * g + kb * b;
    const double u = (b - y) / (2.0 * (1.0 - kb));
    const double v = (r - y) / (2.0 * (1.0 - kr));
    if (e.range == YuvRange::Limited) return {16.0 + 219.0 * y, 224.0 * u, 224.0 * v};
    return {255.0 * y, 255.0 * u, 255.0 * v};
}

std::uint8_t toByte(double v) { return static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L)); }

void requireBgr(const cv::Mat& bgr, bool evenHeight) {
    if (bgr.type() != CV_8UC3 || bgr.cols % 2 != 0 || (evenHeight && bgr.rows % 2 != 0))
        throw std::invalid_argument("YUV encoding needs an 8-bit BGR image of even size");
}

}  // namespace

YuvEncoding defaultYuvEncoding(PixelFormat format, int height) {
    if (format == PixelFormat::Mjpeg) return {YuvMatrix::Bt601, YuvRange::Full};
    return {height >= 720 ? YuvMatrix::Bt709 : YuvMatrix::Bt601, YuvRange::Limited};
}

cv::Mat yuyvToBgr(const std::uint8_t* data, int width, int height, int stride, YuvEncoding encoding) {
    const FixedYuvToRgb k = fixedYuvToRgb(encoding);
    const yuv::YuyvRowVectors vectors = rowKernels().yuyv;
    cv::Mat out(height, width, CV_8UC3);
    cv::parallel_for_(
        cv::Range(0, height),
        [&](const cv::Range& rows) {
            for (int row = rows.start; row < rows.end; ++row)
                yuyvRowToBgr(data + static_cast<std::ptrdiff_t>(row) * stride, out.ptr<std::uint8_t>(row), width, k,
                             vectors);
        },
        stripes(width, height));
    return out;
}

cv::Mat nv12ToBgr(const std::uint8_t* y, int yStride, const std::uint8_t* uv, int uvStride, int width, int height,
                  YuvEncoding encoding) {
    const FixedYuvToRgb k = fixedYuvToRgb(encoding);
    const yuv::Nv12RowVectors vectors = rowKernels().nv12;
    cv::Mat out(height, width, CV_8UC3);
    cv::parallel_for_(
        cv::Range(0, height),
        [&](const cv::Range& rows) {
            for (int row = rows.start; row < rows.end; ++row)
                nv12RowToBgr(y + static_cast<std::ptrdiff_t>(row) * yStride,
                             uv + static_cast<std::ptrdiff_t>(row / 2) * uvStride, out.ptr<std::uint8_t>(row), width, k,
                             vectors);
        },
        stripes(width, height));
    return out;
}

std::vector<std::uint8_t> bgrToYuyv(const cv::Mat& bgr, YuvEncoding e) {
    requireBgr(bgr, false);
    std::vector<std::uint8_t> out(static_cast<std::size_t>(bgr.cols) * bgr.rows * 2);
    std::uint8_t* o = out.data();
    for (int row = 0; row < bgr.rows; ++row) {
        for (int x = 0; x < bgr.cols; x += 2, o += 4) {
            const YuvPixel a = bgrToYuvPixel(e, bgr.at<cv::Vec3b>(row, x));
            const YuvPixel b = bgrToYuvPixel(e, bgr.at<cv::Vec3b>(row, x + 1));
            o[0] = toByte(a.y);
            o[1] = toByte(128.0 + (a.u + b.u) / 2.0);
            o[2] = toByte(b.y);
            o[3] = toByte(128.0 + (a.v + b.v) / 2.0);
        }
    }
    return out;
}

std::vector<std::uint8_t> bgrToNv12(const cv::Mat& bgr, YuvEncoding e) {
    requireBgr(bgr, true);
    const std::size_t w = static_cast<std::size_t>(bgr.cols), h = static_cast<std::size_t>(bgr.rows);
    std::vector<std::uint8_t> out(w * h * 3 / 2);
    for (int row = 0; row < bgr.rows; ++row)
        for (int x = 0; x < bgr.cols; ++x) out[row * w + x] = toByte(bgrToYuvPixel(e, bgr.at<cv::Vec3b>(row, x)).y);
    std::uint8_t* uv = out.data() + w * h;
    for (int row = 0; row < bgr.rows; row += 2) {
        for (int x = 0; x < bgr.cols; x += 2) {
            double u = 0, v = 0;
            for (int dy = 0; dy < 2; ++dy)
                for (int dx = 0; dx < 2; ++dx) {
                    const YuvPixel p = bgrToYuvPixel(e, bgr.at<cv::Vec3b>(row + dy, x + dx));
                    u += p.u / 4.0;
                    v += p.v / 4.0;
                }
            uv[(row / 2) * w + x] = toByte(128.0 + u);
            uv[(row / 2) * w + x + 1] = toByte(128.0 + v);
        }
    }
    return out;
}

}  // namespace arcomp
