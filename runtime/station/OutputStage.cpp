#include "runtime/station/OutputStage.hpp"

#include "runtime/station/ImageFile.hpp"
#include "video/matte/PersonMatte.hpp"
#include "video/pixels/VideoError.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cstdio>
#include <utility>

namespace arcomp {

namespace {

std::string numbered(const char* stem, std::uint64_t index) {
    char name[64];
    std::snprintf(name, sizeof name, "%s-%06llu.png", stem, static_cast<unsigned long long>(index));
    return name;
}

}  // namespace

OutputStage::OutputStage(const OutputConfig& config, double fps, glm::ivec2 size, FrameReadback::Mode readback)
    : config_(config), readback_(readback) {
    if (!config_.videoFile.empty())
        video_ = std::make_unique<VideoFileWriter>(config_.videoFile.string(), config_.videoFourcc, fps,
                                                   cv::Size(size.x, size.y));
}

template <class Step>
void OutputStage::counted(Step&& step) {
    try {
        step();
    } catch (const std::exception& e) {
        ++failures_;
        lastError_ = e.what();
    }
}

void OutputStage::write(const RenderTarget& frame, const cv::Mat& person) {
    const std::uint64_t index = next_++;
    counted([&] { writeMatte(index, person); });
    if (config_.pngDir.empty() && !video_) return;
    counted([&] {
        const std::uint64_t before = std::exchange(inFlight_, index);
        if (readback_.read(frame, image_)) writeFrame(readback_.latencyFrames() == 0 ? index : before, image_);
    });
}

void OutputStage::writeMatte(std::uint64_t index, const cv::Mat& person) {
    if (config_.matteDir.empty()) return;
    std::filesystem::create_directories(config_.matteDir);
    const std::filesystem::path file = config_.matteDir / numbered("matte", index);
    if (!cv::imwrite(file.string(), alphaOf(person))) throw VideoError(file.string(), "matte", "cannot write");
}

void OutputStage::writeFrame(std::uint64_t index, const Image& image) {
    if (!config_.pngDir.empty()) writePng(config_.pngDir / numbered("frame", index), image);
    if (video_) {
        const cv::Mat rgba(image.height, image.width, CV_8UC4, const_cast<std::uint8_t*>(image.rgba.data()));
        cv::cvtColor(rgba, bgr_, cv::COLOR_RGBA2BGR);
        video_->write(bgr_);
    }
}

void OutputStage::finish() {
    counted([&] {
        if (readback_.drain(image_)) writeFrame(inFlight_, image_);
    });
    if (video_) video_->close();
}

}  // namespace arcomp
