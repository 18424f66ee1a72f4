#include "runtime/app/StatsOverlay.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>

namespace arcomp {

namespace {

// Colours as premultiplied RGBA over a translucent panel.
const cv::Scalar kPanel{0, 0, 0, 170};
const cv::Scalar kText{235, 235, 235, 255};
const cv::Scalar kGood{90, 210, 90, 255};
const cv::Scalar kOver{235, 70, 60, 255};
const cv::Scalar kTarget{240, 200, 60, 255};

void text(cv::Mat& image, const std::string& line, int row, const cv::Scalar& colour = kText) {
    cv::putText(image, line, {6, 14 + 14 * row}, cv::FONT_HERSHEY_SIMPLEX, 0.38, colour, 1, cv::LINE_AA);
}

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
    char line[128];
    std::snprintf(line, sizeof line, pattern, a, b, c);
    return line;
}

}  // namespace

void StatsOverlay::add(const FrameStats& stats, const DrawList& drawn, const CameraLine& camera, double frameMs,
                       double targetMs) {
    frameMs_.push_back(frameMs);
    while (frameMs_.size() > kHistory) frameMs_.pop_front();
    draw(stats, drawn, camera, targetMs);
}

void StatsOverlay::draw(const FrameStats& stats, const DrawList& drawn, const CameraLine& camera, double targetMs) {
    image_.create(kHeight, kWidth, CV_8UC4);
    image_.setTo(kPanel);

    // Graph: the last kHistory frames, bars red where over the target.
    const cv::Rect graph(6, 6, kWidth - 12, 60);
    const double top = std::max(2.0 * targetMs, *std::max_element(frameMs_.begin(), frameMs_.end()));
    const double barWidth = static_cast<double>(graph.width) / static_cast<double>(kHistory);
    for (std::size_t i = 0; i < frameMs_.size(); ++i) {
        const int h = std::max(1, static_cast<int>(graph.height * std::min(1.0, frameMs_[i] / top)));
        const int x = graph.x + static_cast<int>(static_cast<double>(i) * barWidth);
        cv::rectangle(image_, cv::Rect(x, graph.y + graph.height - h, std::max(1, static_cast<int>(barWidth)), h),
                      frameMs_[i] > targetMs ? kOver : kGood, cv::FILLED);
    }
    const int targetY = graph.y + graph.height - static_cast<int>(graph.height * targetMs / top);
    cv::line(image_, {graph.x, targetY}, {graph.x + graph.width, targetY}, kTarget, 1);

    int row = 5;
    text(image_, format("frame %.1f ms, target %.1f ms", frameMs_.back(), targetMs), row++);
    text(image_,
         format("capture %.1f  matte %.1f  track %.1f", stats.captureMs, stats.matteMs, stats.trackMs) + " (" +
             std::to_string(stats.people) + " people)",
         row++);
    text(image_,
         format("render %.1f", stats.renderMs) +
             format("  holdout %.1f  comp. %.1f", stats.holdoutMs, stats.compositeMs),
         row++);
    if (stats.budget)
        text(image_,
             format("budget: predicted %.1f ms, measured %.1f ms, quality %.2f", stats.budget->measuredPredictedMs,
                    stats.budget->measuredMs, stats.budget->quality),
             row++);
    else
        text(image_, "budget: off", row++);

    std::array<int, 4> perLevel{};
    std::array<int, kShadingCount> perShading{};
    int proxies = 0;
    for (const DrawItem& item : drawn.items) {
        ++perLevel[std::min<std::size_t>(item.level, perLevel.size() - 1)];
        ++perShading[static_cast<int>(item.shading)];
        proxies += item.model != nullptr;  // grouping proxies are drawn with their own matrix
    }
    text(image_,
         "levels 0/1/2/3+: " + std::to_string(perLevel[0]) + "/" + std::to_string(perLevel[1]) + "/" +
             std::to_string(perLevel[2]) + "/" + std::to_string(perLevel[3]) + "   proxies: " + std::to_string(proxies),
         row++);
    text(image_,
         "unlit/flat/gouraud/phong: " + std::to_string(perShading[0]) + "/" + std::to_string(perShading[1]) + "/" +
             std::to_string(perShading[2]) + "/" + std::to_string(perShading[3]),
         row++);
    const bool streaming = camera.state.status == SourceStatus::Streaming;
    text(image_,
         std::filesystem::path(camera.name).filename().string() + ": " +
             std::string(sourceStatusName(camera.state.status)) + ", " + std::to_string(camera.drops) + " dropped",
         row++, streaming ? kText : kOver);
    if (!streaming && !camera.state.reason.empty()) text(image_, camera.state.reason.substr(0, 60), row++, kOver);
}

}  // namespace arcomp
