#include "tools/bench/report/LinePlot.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace arcomp {

namespace {

const cv::Scalar kPalette[] = {{200, 90, 40},  {40, 60, 210},  {60, 160, 60},
                               {160, 60, 160}, {30, 150, 200}, {90, 90, 90}};
const cv::Scalar kInk{30, 30, 30};

// 1, 2 or 5 times a power of ten, so that about `ticks` gridlines fit.
double niceStep(double span, int ticks) {
    const double raw = span / ticks;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0})
        if (raw <= m * power) return m * power;
    return 10.0 * power;
}

std::string label(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

}  // namespace

LinePlot::LinePlot(std::string title, std::string xLabel, std::string yLabel)
    : title_(std::move(title)), xLabel_(std::move(xLabel)), yLabel_(std::move(yLabel)) {}

void LinePlot::addSeries(std::string name, std::vector<double> x, std::vector<double> y) {
    if (x.size() != y.size()) throw std::invalid_argument("LinePlot series '" + name + "': x and y differ in length");
    series_.push_back({std::move(name), std::move(x), std::move(y)});
}

void LinePlot::addLevel(std::string name, double y) { levels_.push_back({std::move(name), y}); }

void LinePlot::writePng(const std::filesystem::path& file, int width, int height) const {
    double x0 = std::numeric_limits<double>::max(), x1 = std::numeric_limits<double>::lowest();
    double y1 = 0.0;
    for (const Series& s : series_)
        for (std::size_t i = 0; i < s.x.size(); ++i) {
            if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
            x0 = std::min(x0, s.x[i]);
            x1 = std::max(x1, s.x[i]);
            y1 = std::max(y1, s.y[i]);
        }
    for (const Level& l : levels_) y1 = std::max(y1, l.y);
    if (x0 > x1) x0 = 0.0, x1 = 1.0;
    if (x1 == x0) x1 = x0 + 1.0;
    if (y1 <= 0.0) y1 = 1.0;
    y1 *= 1.05;

    cv::Mat image(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
    const cv::Rect area(70, 40, width - 90, height - 90);
    auto toPixel = [&](double x, double y) {
        return cv::Point(area.x + static_cast<int>(std::lround((x - x0) / (x1 - x0) * area.width)),
                         area.y + area.height - static_cast<int>(std::lround(y / y1 * area.height)));
    };

    const double xStep = niceStep(x1 - x0, 8), yStep = niceStep(y1, 6);
    for (double y = 0.0; y <= y1; y += yStep) {
        cv::line(image, toPixel(x0, y), toPixel(x1, y), {225, 225, 225});
        cv::putText(image, label(y), toPixel(x0, y) + cv::Point(-60, 4), cv::FONT_HERSHEY_SIMPLEX, 0.4, kInk);
    }
    for (double x = std::ceil(x0 / xStep) * xStep; x <= x1; x += xStep)
        cv::putText(image, label(x), toPixel(x, 0.0) + cv::Point(-10, 18), cv::FONT_HERSHEY_SIMPLEX, 0.4, kInk);
    cv::rectangle(image, area, kInk);
    cv::putText(image, title_, {area.x, 25}, cv::FONT_HERSHEY_SIMPLEX, 0.6, kInk);
    cv::putText(image, xLabel_, {area.x + area.width / 2, height - 15}, cv::FONT_HERSHEY_SIMPLEX, 0.5, kInk);
    cv::putText(image, yLabel_, {8, area.y - 8}, cv::FONT_HERSHEY_SIMPLEX, 0.5, kInk);

    // The legend's right edge sits inside the plot whatever its names' length.
    int nameWidth = 0;
    auto widen = [&](const std::string& name) {
        int baseline = 0;
        nameWidth = std::max(nameWidth, cv::getTextSize(name, cv::FONT_HERSHEY_SIMPLEX, 0.45, 1, &baseline).width);
    };
    for (const Level& l : levels_) widen(l.name);
    for (const Series& s : series_) widen(s.name);
    const int legendX = area.x + area.width - nameWidth - 46;
    int legendY = area.y + 18;
    auto legend = [&](const std::string& name, const cv::Scalar& colour) {
        cv::line(image, {legendX, legendY - 4}, {legendX + 30, legendY - 4}, colour, 2);
        cv::putText(image, name, {legendX + 38, legendY}, cv::FONT_HERSHEY_SIMPLEX, 0.45, kInk);
        legendY += 18;
    };
    for (const Level& l : levels_) {
        cv::line(image, toPixel(x0, l.y), toPixel(x1, l.y), {0, 0, 0}, 1, cv::LINE_AA);
        legend(l.name, {0, 0, 0});
    }
    for (std::size_t k = 0; k < series_.size(); ++k) {
        const Series& s = series_[k];
        const cv::Scalar colour = kPalette[k % std::size(kPalette)];
        for (std::size_t i = 1; i < s.x.size(); ++i)
            if (std::isfinite(s.y[i - 1]) && std::isfinite(s.y[i]))
                cv::line(image, toPixel(s.x[i - 1], s.y[i - 1]), toPixel(s.x[i], s.y[i]), colour, 1, cv::LINE_AA);
        legend(s.name, colour);
    }

    if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
    if (!cv::imwrite(file.string(), image)) throw std::runtime_error("cannot write plot " + file.string());
}

}  // namespace arcomp
