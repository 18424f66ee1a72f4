#include "tools/bench/report/Ssim.hpp"

#include <opencv2/imgproc.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace arcomp {

double ssim(const cv::Mat& a, const cv::Mat& b, const cv::Mat& mask) {
    constexpr int kWindow = 11;
    constexpr double kSigma = 1.5, kL = 255.0;
    constexpr double C1 = (0.01 * kL) * (0.01 * kL), C2 = (0.03 * kL) * (0.03 * kL);
    if (a.size() != b.size() || a.type() != b.type() || a.depth() != CV_8U)
        throw std::invalid_argument("ssim: the images must both be 8-bit and alike; got " + std::to_string(a.cols) +
                                    "x" + std::to_string(a.rows) + " type " + std::to_string(a.type()) + " and " +
                                    std::to_string(b.cols) + "x" + std::to_string(b.rows) + " type " +
                                    std::to_string(b.type()));
    if (a.cols < kWindow || a.rows < kWindow)
        throw std::invalid_argument("ssim: images of " + std::to_string(a.cols) + "x" + std::to_string(a.rows) +
                                    " are smaller than the 11x11 window");
    if (!mask.empty() && (mask.size() != a.size() || mask.type() != CV_8UC1))
        throw std::invalid_argument("ssim: the mask must be 8-bit, one channel, " + std::to_string(a.cols) + "x" +
                                    std::to_string(a.rows));
    // Channel by channel: OpenCV's matrix expressions add a scalar to the
    // first channel only of a multi-channel matrix.
    std::vector<cv::Mat> channelsA, channelsB;
    cv::split(a, channelsA);
    cv::split(b, channelsB);
    const auto blur = [](const cv::Mat& m) {
        cv::Mat out;
        cv::GaussianBlur(m, out, cv::Size(kWindow, kWindow), kSigma, kSigma, cv::BORDER_REFLECT);
        return out;
    };
    const int border = kWindow / 2;
    const cv::Rect inside(border, border, a.cols - 2 * border, a.rows - 2 * border);
    const cv::Mat counted = mask.empty() ? cv::Mat() : mask(inside);
    if (!counted.empty() && cv::countNonZero(counted) == 0)
        throw std::invalid_argument("ssim: the mask selects no pixel inside the 5-pixel border");
    double sum = 0.0;
    for (std::size_t c = 0; c < channelsA.size(); ++c) {
        cv::Mat x, y;
        channelsA[c].convertTo(x, CV_64F);
        channelsB[c].convertTo(y, CV_64F);
        const cv::Mat muX = blur(x), muY = blur(y);
        const cv::Mat muXX = muX.mul(muX), muYY = muY.mul(muY), muXY = muX.mul(muY);
        const cv::Mat sigmaXX = blur(x.mul(x)) - muXX, sigmaYY = blur(y.mul(y)) - muYY, sigmaXY = blur(x.mul(y)) - muXY;
        const cv::Mat numerator = (2.0 * muXY + C1).mul(2.0 * sigmaXY + C2);
        const cv::Mat denominator = (muXX + muYY + C1).mul(sigmaXX + sigmaYY + C2);
        cv::Mat map;
        cv::divide(numerator, denominator, map);
        sum += cv::mean(map(inside), counted)[0];
    }
    return sum / static_cast<double>(channelsA.size());
}

}  // namespace arcomp
