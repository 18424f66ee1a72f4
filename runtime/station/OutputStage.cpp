#include "runtime/station/OutputStage.hpp"

#include "runtime/station/ImageFile.hpp"
#include "video/matte/PersonMatte.hpp"
#include "video/pixels/VideoError.hpp"
#include "video/streams/H264Recording.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace arcomp {

namespace {

std::string numbered(const char* stem, std::uint64_t index, const char* extension = ".png") {
    char name[64];
    std::snprintf(name, sizeof name, "%s-%06llu%s", stem, static_cast<unsigned long long>(index), extension);
    return name;
}

}  // namespace

OutputStage::OutputStage(const OutputConfig& config, double fps, glm::ivec2 size, FrameReadback::Mode readback,
                         WhenFull recording)
    : config_(config), readback_(readback), fps_(fps), size_(size) {
    if (!config_.streams.empty()) {
        std::vector<StreamSpec> specs;
        for (const StreamConfig& s : config_.streams) specs.push_back(s.spec);
        streams_ = std::make_unique<StreamOutputs>(specs, RawVideo{size.x, size.y, fps});
    }
    if (config_.videoFile.empty()) return;
    if (isH264Container(config_.videoFile))
        recording_ = openH264Recording(config_.videoFile, config_.videoEncoding, {size.x, size.y, fps}, recording);
    else
        video_ = std::make_unique<VideoFileWriter>(config_.videoFile.string(), config_.videoFourcc, fps,
                                                   cv::Size(size.x, size.y));
}

void OutputStage::preflight(const OutputConfig& config) {
    if (isH264Container(config.videoFile))
        if (const EncoderChoice c = chooseH264Encoder(config.videoEncoding.encoder); c.element.empty())
            throw BadInput(config.videoFileAt.empty() ? config.videoFile.string() : config.videoFileAt,
                           "output.video_file", c.warning);
    for (const StreamConfig& s : config.streams)
        if (const std::string missing = missingStreamElements(s.spec); !missing.empty())
            throw BadInput(s.at, "output.streams " + s.spec.name, missing);
}

std::vector<StreamStatus> OutputStage::streamStatus() const {
    return streams_ ? streams_->status() : std::vector<StreamStatus>{};
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
    if (config_.pngDir.empty() && !video_ && !recording_ && !streams_ && snapshots_.empty() && clips_.empty()) return;
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

void OutputStage::snapshot(const std::filesystem::path& folder) { snapshots_.push_back({next_, folder}); }

void OutputStage::clip(const std::filesystem::path& folder, double seconds) {
    const auto frames = static_cast<std::uint64_t>(std::max(1.0, std::round(seconds * fps_)));
    clips_.push_back({next_, folder, frames, nullptr});
}

void OutputStage::writeFrame(std::uint64_t index, const Image& image) {
    if (!config_.pngDir.empty()) counted([&] { writePng(config_.pngDir / numbered("frame", index), image); });
    if (recording_) record(image);
    if (streams_ && image.width == size_.x && image.height == size_.y) streams_->push(image.rgba.data());
    const bool toVideo =
        video_ || std::any_of(clips_.begin(), clips_.end(), [&](const Clip& c) { return c.index <= index; });
    if (toVideo) {
        const cv::Mat rgba(image.height, image.width, CV_8UC4, const_cast<std::uint8_t*>(image.rgba.data()));
        cv::cvtColor(rgba, bgr_, cv::COLOR_RGBA2BGR);
        if (video_) counted([&] { video_->write(bgr_); });
    }
    writeRequested(index, image);
}

// A recording that fails (a full disk) is one failure, kept with its
// reason; its later frames are dropped and counted.
void OutputStage::record(const Image& image) {
    if (image.width != size_.x || image.height != size_.y) {
        ++failures_;
        lastError_ = config_.videoFile.string() + ": frame of " + std::to_string(image.width) + "x" +
                     std::to_string(image.height) + ", the recording was opened for " + std::to_string(size_.x) + "x" +
                     std::to_string(size_.y);
        return;
    }
    recording_->push(image.rgba.data());
    noteRecordingFailure();
}

void OutputStage::noteRecordingFailure() {
    if (recordingFailureCounted_ || recording_->state() != PipelineState::Failed) return;
    recordingFailureCounted_ = true;
    ++failures_;
    lastError_ = recording_->name() + ": " + recording_->error();
}

// Snapshots and clips from `index` on; each failure is counted on its own,
// and a clip that cannot be opened or written is given up.
void OutputStage::writeRequested(std::uint64_t index, const Image& image) {
    for (const Snapshot& s : snapshots_)
        if (s.index <= index)
            counted([&] {
                std::filesystem::create_directories(s.folder);
                writePng(s.folder / numbered("snapshot", s.index), image);
                ++snapshotsWritten_;
            });
    std::erase_if(snapshots_, [&](const Snapshot& s) { return s.index <= index; });
    for (Clip& c : clips_) {
        if (c.index > index) continue;
        counted([&] {
            if (!c.file) {
                std::filesystem::create_directories(c.folder);
                c.file = std::make_unique<VideoFileWriter>((c.folder / numbered("clip", c.index, ".avi")).string(),
                                                           config_.videoFourcc, fps_, cv::Size(size_.x, size_.y));
            }
            c.file->write(bgr_);
            if (--c.frames == 0) {
                c.file->close();
                ++clipsWritten_;
            }
        });
        if (!c.file) c.frames = 0;
    }
    std::erase_if(clips_, [&](const Clip& c) { return c.index <= index && c.frames == 0; });
}

void OutputStage::finish() {
    counted([&] {
        if (readback_.drain(image_)) writeFrame(inFlight_, image_);
    });
    if (video_) video_->close();
    if (recording_) {
        recording_->close();
        noteRecordingFailure();
    }
    if (streams_) streams_->close();
    // A clip cut short by the end of the input keeps what it has.
    for (Clip& c : clips_)
        if (c.file) {
            c.file->close();
            ++clipsWritten_;
        }
    clips_.clear();
}

}  // namespace arcomp
