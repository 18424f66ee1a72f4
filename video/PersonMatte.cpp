#include "video/PersonMatte.hpp"

#include <opencv2/core.hpp>

namespace arcomp {

cv::Mat alphaOf(const cv::Mat& person) {
    cv::Mat alpha;
    cv::extractChannel(person, alpha, 3);
    return alpha;
}

void premultiply(const cv::Mat& frame, const cv::Mat& alpha, cv::Mat& person) {
    CV_Assert(frame.type() == CV_8UC3 && alpha.type() == CV_8UC1 && frame.size() == alpha.size());
    person.create(frame.size(), CV_8UC4);
    cv::parallel_for_(cv::Range(0, frame.rows), [&](const cv::Range& rows) {
        for (int y = rows.start; y < rows.end; ++y) {
            const std::uint8_t* c = frame.ptr<std::uint8_t>(y);
            const std::uint8_t* a = alpha.ptr<std::uint8_t>(y);
            std::uint8_t* o = person.ptr<std::uint8_t>(y);
            for (int x = 0; x < frame.cols; ++x, c += 3, o += 4) {
                const unsigned k = a[x];
                // (v * k + 127) / 255 without a division: exact for 8-bit inputs.
                auto mul = [k](unsigned v) {
                    const unsigned t = v * k + 128;
                    return static_cast<std::uint8_t>((t + (t >> 8)) >> 8);
                };
                o[0] = mul(c[0]);
                o[1] = mul(c[1]);
                o[2] = mul(c[2]);
                o[3] = static_cast<std::uint8_t>(k);
            }
        }
    });
}

} // namespace arcomp
