#include "video/sources/TestPatternSource.hpp"
#include "graph/core/JoinText.hpp"

#include "video/pixels/VideoError.hpp"

#include <opencv2/imgproc.hpp>

namespace arcomp {

TestPatternSource::TestPatternSource(TestPatternOptions options) : options_(options) {
    if (options_.width < 16 || options_.height < 16 || options_.width > 16384 || options_.height > 16384 ||
        !(options_.fps > 0.0 && options_.fps <= 1000.0))
        throw VideoError("pattern", "",
                         joinText("size ", options_.width, "x", options_.height, " at ", options_.fps,
                                  " fps: expected 16..16384 pixels and 0 < fps <= 1000"));
}

std::string TestPatternSource::name() const {
    return joinText("pattern ", options_.width, "x", options_.height, "@", options_.fps);
}

cv::Point TestPatternSource::circleCentre(std::uint64_t index) const {
    // One width every four seconds, whatever the rate, so motion looks the same at any fps.
    const double seconds = static_cast<double>(index) / options_.fps;
    const double travel = std::fmod(seconds / 4.0, 1.0);
    return {static_cast<int>(travel * options_.width), options_.height / 2};
}

cv::Mat TestPatternSource::render(std::uint64_t index) const {
    const int w = options_.width, h = options_.height;
    cv::Mat img(h, w, CV_8UC3);
    // Top quarter: the eight SMPTE-style bars, for eyeballing colour conversion.
    static const cv::Scalar bars[] = {{255, 255, 255}, {0, 255, 255}, {255, 255, 0}, {0, 255, 0},
                                      {255, 0, 255},   {0, 0, 255},   {255, 0, 0},   {0, 0, 0}};
    for (int i = 0; i < 8; ++i)
        cv::rectangle(img, cv::Point(i * w / 8, 0), cv::Point((i + 1) * w / 8 - 1, h / 4 - 1), bars[i], cv::FILLED);
    // The rest: a grey ramp left to right.
    for (int y = h / 4; y < h; ++y) {
        auto* row = img.ptr<cv::Vec3b>(y);
        for (int x = 0; x < w; ++x) {
            const auto g = static_cast<std::uint8_t>(32 + 160 * x / w);
            row[x] = {g, g, g};
        }
    }
    const int r = std::max(4, h / 10);
    cv::circle(img, circleCentre(index), r, {40, 160, 230}, cv::FILLED, cv::LINE_8);
    // A square bouncing up and down once every two seconds.
    const double phase = std::fmod(static_cast<double>(index) / options_.fps / 2.0, 1.0);
    const double bounce = phase < 0.5 ? phase * 2.0 : 2.0 - phase * 2.0;
    const int sy = h / 4 + static_cast<int>(bounce * (h * 3 / 4 - 2 * r));
    cv::rectangle(img, cv::Rect(w * 3 / 4, sy, 2 * r, 2 * r), {200, 60, 60}, cv::FILLED);
    cv::putText(img, joinText("#", index), cv::Point(w / 40, h - h / 20), cv::FONT_HERSHEY_SIMPLEX, h / 240.0,
                {255, 255, 255}, std::max(1, h / 240), cv::LINE_8);
    return img;
}

GrabResult TestPatternSource::grab() {
    const std::uint64_t k = next_++;
    Frame f;
    f.sequence = k;
    f.timestamp = std::chrono::nanoseconds(static_cast<std::int64_t>(static_cast<double>(k) * 1e9 / options_.fps));
    f.captured = options_.paced ? pacer_.release(f.timestamp) : std::chrono::steady_clock::now();
    f.image = render(k);
    f.format = PixelFormat::Bgr;
    return {std::move(f), {SourceStatus::Streaming, {}}};
}

}  // namespace arcomp
