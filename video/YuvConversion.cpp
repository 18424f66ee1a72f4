#include "video/YuvConversion.hpp"

#include <opencv2/core/utility.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace arcomp {

namespace {

struct LumaWeights {
    double kr;
    double kb;
};

// ITU-R BT.601 and BT.709: luma weights of R and B (G takes the rest).
LumaWeights lumaWeights(YuvMatrix m) {
    return m == YuvMatrix::Bt709 ? LumaWeights{0.2126, 0.0722} : LumaWeights{0.299, 0.114};
}

// Per-encoding constants for R = a(Y - y0) + rv V', G = a(Y - y0) - gu U' - gv V',
// B = a(Y - y0) + bu U' with U' = U - 128, V' = V - 128, in 16.16 fixed point.
struct YuvToRgb {
    int y0;
    int a, rv, gu, gv, bu;
};

YuvToRgb yuvToRgb(YuvEncoding e) {
    const auto [kr, kb] = lumaWeights(e.matrix);
    const double kg = 1.0 - kr - kb;
    const bool limited = e.range == YuvRange::Limited;
    const double ys = limited ? 255.0 / 219.0 : 1.0;
    const double cs = limited ? 255.0 / 224.0 : 1.0;
    const double rv = 2.0 * (1.0 - kr) * cs;
    const double bu = 2.0 * (1.0 - kb) * cs;
    const double gu = bu * kb / kg;
    const double gv = rv * kr / kg;
    auto fx = [](double v) { return static_cast<int>(std::lround(v * 65536.0)); };
    return {limited ? 16 : 0, fx(ys), fx(rv), fx(gu), fx(gv), fx(bu)};
}

inline std::uint8_t clampByte(int v16) {
    return static_cast<std::uint8_t>(std::clamp((v16 + 32768) >> 16, 0, 255));
}

inline void putBgr(std::uint8_t* out, const YuvToRgb& k, int y, int u, int v) {
    const int l = k.a * (y - k.y0);
    out[0] = clampByte(l + k.bu * u);
    out[1] = clampByte(l - k.gu * u - k.gv * v);
    out[2] = clampByte(l + k.rv * v);
}

struct YuvPixel {
    double y, u, v; // u, v centred on 128
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

} // namespace

YuvEncoding defaultYuvEncoding(PixelFormat format, int height) {
    if (format == PixelFormat::Mjpeg) return {YuvMatrix::Bt601, YuvRange::Full};
    return {height >= 720 ? YuvMatrix::Bt709 : YuvMatrix::Bt601, YuvRange::Limited};
}

cv::Mat yuyvToBgr(const std::uint8_t* data, int width, int height, int stride, YuvEncoding encoding) {
    const YuvToRgb k = yuvToRgb(encoding);
    cv::Mat out(height, width, CV_8UC3);
    cv::parallel_for_(cv::Range(0, height), [&](const cv::Range& rows) {
        for (int row = rows.start; row < rows.end; ++row) {
            const std::uint8_t* in = data + static_cast<std::ptrdiff_t>(row) * stride;
            std::uint8_t* o = out.ptr<std::uint8_t>(row);
            for (int x = 0; x + 1 < width; x += 2, in += 4, o += 6) {
                const int u = in[1] - 128, v = in[3] - 128;
                putBgr(o, k, in[0], u, v);
                putBgr(o + 3, k, in[2], u, v);
            }
        }
    });
    return out;
}

cv::Mat nv12ToBgr(const std::uint8_t* y, int yStride, const std::uint8_t* uv, int uvStride, int width, int height,
                  YuvEncoding encoding) {
    const YuvToRgb k = yuvToRgb(encoding);
    cv::Mat out(height, width, CV_8UC3);
    cv::parallel_for_(cv::Range(0, height), [&](const cv::Range& rows) {
        for (int row = rows.start; row < rows.end; ++row) {
            const std::uint8_t* yr = y + static_cast<std::ptrdiff_t>(row) * yStride;
            const std::uint8_t* cr = uv + static_cast<std::ptrdiff_t>(row / 2) * uvStride;
            std::uint8_t* o = out.ptr<std::uint8_t>(row);
            for (int x = 0; x < width; ++x, o += 3) {
                const int u = cr[x & ~1] - 128, v = cr[(x & ~1) + 1] - 128;
                putBgr(o, k, yr[x], u, v);
            }
        }
    });
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
        for (int x = 0; x < bgr.cols; ++x)
            out[row * w + x] = toByte(bgrToYuvPixel(e, bgr.at<cv::Vec3b>(row, x)).y);
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

} // namespace arcomp
