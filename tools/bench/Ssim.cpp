#include "tools/bench/Ssim.hpp"

#include <opencv2/imgproc.hpp>

#include <stdexcept>
#include <string>

namespace arcomp {

double ssim(const cv::Mat& a, const cv::Mat& b) {
    constexpr int kWindow = 11;
    constexpr double kSigma = 1.5, kL = 255.0;
    constexpr double C1 = (0.01 * kL) * (0.01 * kL), C2 = (0.03 * kL) * (0.03 * kL);
    if (a.size() != b.size() || a.type() != b.type() || a.depth() != CV_8U)
        throw std::invalid_argument("ssim: the images must both be 8-bit and alike; got " + std::to_string(a.cols) + "x" +
                                    std::to_string(a.rows) + " type " + std::to_string(a.type()) + " and " +
                                    std::to_string(b.cols) + "x" + std::to_string(b.rows) + " type " + std::to_string(b.type()));
    if (a.cols < kWindow || a.rows < kWindow)
        throw std::invalid_argument("ssim: images of " + std::to_string(a.cols) + "x" + std::to_string(a.rows) +
                                    " are smaller than the 11x11 window");
    cv::Mat x, y;
    a.convertTo(x, CV_64F);
    b.convertTo(y, CV_64F);
    const auto blur = [](const cv::Mat& m) {
        cv::Mat out;
        cv::GaussianBlur(m, out, cv::Size(kWindow, kWindow), kSigma, kSigma, cv::BORDER_REFLECT);
        return out;
    };
    const cv::Mat muX = blur(x), muY = blur(y);
    const cv::Mat muXX = muX.mul(muX), muYY = muY.mul(muY), muXY = muX.mul(muY);
    const cv::Mat sigmaXX = blur(x.mul(x)) - muXX, sigmaYY = blur(y.mul(y)) - muYY, sigmaXY = blur(x.mul(y)) - muXY;
    cv::Mat numerator = (2.0 * muXY + C1).mul(2.0 * sigmaXY + C2);
    cv::Mat denominator = (muXX + muYY + C1).mul(sigmaXX + sigmaYY + C2);
    cv::Mat map;
    cv::divide(numerator, denominator, map);
    const int border = kWindow / 2;
    const cv::Scalar means = cv::mean(map(cv::Rect(border, border, a.cols - 2 * border, a.rows - 2 * border)));
    double sum = 0.0;
    for (int c = 0; c < a.channels(); ++c) sum += means[c];
    return sum / a.channels();
}

} // namespace arcomp
