#include "runtime/OutputStage.hpp"

#include "runtime/ImageFile.hpp"
#include "video/PersonMatte.hpp"
#include "video/VideoError.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cstdio>

namespace arcomp {

namespace {

std::string numbered(const char* stem, std::uint64_t index) {
    char name[64];
    std::snprintf(name, sizeof name, "%s-%06llu.png", stem, static_cast<unsigned long long>(index));
    return name;
}

} // namespace

OutputStage::OutputStage(const OutputConfig& config, double fps, glm::ivec2 size) : config_(config) {
    if (!config_.videoFile.empty())
        video_ = std::make_unique<VideoFileWriter>(config_.videoFile.string(), config_.videoFourcc, fps,
                                                   cv::Size(size.x, size.y));
}

void OutputStage::write(const RenderTarget& frame, const cv::Mat& person) {
    try {
        writeFiles(next_++, frame, person);
    } catch (const std::exception& e) {
        ++failures_;
        lastError_ = e.what();
    }
}

void OutputStage::writeFiles(std::uint64_t index, const RenderTarget& frame, const cv::Mat& person) {
    if (!config_.matteDir.empty()) {
        std::filesystem::create_directories(config_.matteDir);
        const std::filesystem::path file = config_.matteDir / numbered("matte", index);
        if (!cv::imwrite(file.string(), alphaOf(person))) throw VideoError(file.string(), "matte", "cannot write");
    }
    if (config_.pngDir.empty() && !video_) return;
    frame.read(image_);
    if (!config_.pngDir.empty()) writePng(config_.pngDir / numbered("frame", index), image_);
    if (video_) {
        const cv::Mat rgba(image_.height, image_.width, CV_8UC4, image_.rgba.data());
        cv::cvtColor(rgba, bgr_, cv::COLOR_RGBA2BGR);
        video_->write(bgr_);
    }
}

void OutputStage::finish() {
    if (video_) video_->close();
}

} // namespace arcomp
