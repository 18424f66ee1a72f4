#include "tools/bench/scenes/NumberedFrames.hpp"

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace arcomp {

namespace {
constexpr int kNumberSquare = 16;
}  // namespace

cv::Mat numberedFrame(int index, cv::Size size) {
    cv::Mat frame(size, CV_8UC3);
    for (int y = 0; y < size.height; ++y)
        for (int x = 0; x < size.width; ++x)
            frame.at<cv::Vec3b>(y, x) = {static_cast<uchar>(x * 255 / size.width),
                                         static_cast<uchar>(y * 255 / size.height),
                                         static_cast<uchar>(128 + 100 * std::sin((x + y) * 0.02 + index * 0.1))};
    const cv::Point centre(size.width / 2 + static_cast<int>(size.width / 4 * std::sin(index * 0.2)), size.height / 2);
    cv::circle(frame, centre, size.height / 6, {40, 200, 240}, cv::FILLED, cv::LINE_AA);
    cv::putText(frame, std::to_string(index), {size.width / 3, size.height - 20}, cv::FONT_HERSHEY_SIMPLEX, 1.0,
                {255, 255, 255}, 2, cv::LINE_AA);
    // As soft as a camera's picture: 4:2:0 keeps colour at half the
    // resolution, and a razor-sharp colour edge alone would cost 2-3 dB.
    cv::GaussianBlur(frame, frame, {7, 7}, 2.0);
    for (int bit = 0; bit < kNumberBits; ++bit) {
        const bool one = (index >> bit & 1) != 0;
        const cv::Rect top(bit * kNumberSquare, 0, kNumberSquare, kNumberSquare);
        frame(top).setTo(one ? cv::Scalar::all(255) : cv::Scalar::all(0));
        frame(top + cv::Point(0, kNumberSquare)).setTo(one ? cv::Scalar::all(0) : cv::Scalar::all(255));
    }
    return frame;
}

int frameNumberOf(const cv::Mat& bgr) {
    cv::Mat grey;
    cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
    int number = 0;
    for (int bit = 0; bit < kNumberBits; ++bit) {
        const cv::Rect top(bit * kNumberSquare + 4, 4, kNumberSquare - 8, kNumberSquare - 8);
        const double a = cv::mean(grey(top))[0], b = cv::mean(grey(top + cv::Point(0, kNumberSquare)))[0];
        if (std::abs(a - b) < 128.0) return -1;
        if (a > b) number |= 1 << bit;
    }
    return number;
}

std::filesystem::path writeNumberedVideo(const std::filesystem::path& file, int count, cv::Size size, double fps) {
    cv::VideoWriter out(file.string(), cv::CAP_FFMPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), fps, size);
    if (!out.isOpened()) throw std::runtime_error(file.string() + ": cannot write");
    for (int i = 0; i < count; ++i) out.write(numberedFrame(i, size));
    return file;
}

}  // namespace arcomp
