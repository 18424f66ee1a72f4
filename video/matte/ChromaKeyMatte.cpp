#include "video/matte/ChromaKeyMatte.hpp"

#include "video/pixels/VideoError.hpp"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>

namespace arcomp {

namespace {

// BT.709 luma weights on encoded R, G, B.
constexpr float kR = 0.2126f, kG = 0.7152f, kB = 0.0722f;

float smoothstep01(float t) {
    t = std::clamp(t, 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

}  // namespace

float chromaKeyAlpha(float d, float similarity, float smoothness) {
    if (smoothness <= 0.0f) return d > similarity ? 1.0f : 0.0f;
    return smoothstep01((d - similarity) / smoothness);
}

float chromaSpillKeep(float d, float similarity, float spill) {
    if (spill <= 0.0f) return 1.0f;
    // A power above 1 keeps the removal concentrated right at the key edge.
    return std::pow(std::clamp((d - similarity) / spill, 0.0f, 1.0f), 1.5f);
}

cv::Vec2f cbcrOf(cv::Vec3b bgr) {
    const float b = bgr[0] / 255.0f, g = bgr[1] / 255.0f, r = bgr[2] / 255.0f;
    const float y = kR * r + kG * g + kB * b;
    return {(b - y) / (2.0f * (1.0f - kB)), (r - y) / (2.0f * (1.0f - kR))};
}

ChromaKeyMatte::ChromaKeyMatte(const ChromaKeySpec& spec) : alpha_(256 * 256), keep_(256 * 256) {
    if (!(spec.similarity >= 0.0f && spec.smoothness >= 0.0f && spec.spill >= 0.0f))
        throw VideoError("chroma key", "settings", "similarity, smoothness and spill must be >= 0");
    const cv::Vec2f key = cbcrOf(spec.keyBgr);
    for (int cb = 0; cb < 256; ++cb)
        for (int cr = 0; cr < 256; ++cr) {
            const float d = std::hypot((cb - 128) / 255.0f - key[0], (cr - 128) / 255.0f - key[1]);
            const std::size_t i = static_cast<std::size_t>(cb) * 256 + static_cast<std::size_t>(cr);
            alpha_[i] =
                static_cast<std::uint8_t>(std::lround(255.0f * chromaKeyAlpha(d, spec.similarity, spec.smoothness)));
            keep_[i] = static_cast<std::uint8_t>(std::lround(255.0f * chromaSpillKeep(d, spec.similarity, spec.spill)));
        }
}

void ChromaKeyMatte::apply(const cv::Mat& frame, cv::Mat& person) {
    CV_Assert(frame.type() == CV_8UC3);
    person.create(frame.size(), CV_8UC4);
    constexpr float kCb = 1.0f / (2.0f * (1.0f - kB)), kCr = 1.0f / (2.0f * (1.0f - kR));
    cv::parallel_for_(cv::Range(0, frame.rows), [&](const cv::Range& rows) {
        for (int yRow = rows.start; yRow < rows.end; ++yRow) {
            const std::uint8_t* c = frame.ptr<std::uint8_t>(yRow);
            std::uint8_t* o = person.ptr<std::uint8_t>(yRow);
            for (int x = 0; x < frame.cols; ++x, c += 3, o += 4) {
                const int b = c[0], g = c[1], r = c[2];
                const float y = kR * static_cast<float>(r) + kG * static_cast<float>(g) + kB * static_cast<float>(b);
                const int cb =
                    std::clamp(static_cast<int>(std::lround((static_cast<float>(b) - y) * kCb)) + 128, 0, 255);
                const int cr =
                    std::clamp(static_cast<int>(std::lround((static_cast<float>(r) - y) * kCr)) + 128, 0, 255);
                const std::size_t i = static_cast<std::size_t>(cb) * 256 + static_cast<std::size_t>(cr);
                const int a = alpha_[i];
                const int keep = keep_[i];
                const int luma = static_cast<int>(std::lround(y));
                // Spill: blend towards luma by (1 - keep), then premultiply by alpha.
                auto out = [&](int v) {
                    const int despilled = luma * 255 + (v - luma) * keep;  // * 255
                    return static_cast<std::uint8_t>(std::clamp((despilled * a + 32512) / 65025, 0, 255));
                };
                o[0] = out(b);
                o[1] = out(g);
                o[2] = out(r);
                o[3] = static_cast<std::uint8_t>(a);
            }
        }
    });
}

}  // namespace arcomp
