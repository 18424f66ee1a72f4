#include "video/sources/FileSource.hpp"
#include "graph/core/JoinText.hpp"

#include "video/pixels/VideoError.hpp"

#include <spdlog/spdlog.h>

#include <cmath>
#include <filesystem>

#include <unistd.h>

namespace arcomp {

namespace {

void checkReadable(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (!fs::exists(st)) throw VideoError(path, "", "file does not exist");
    if (fs::is_directory(st)) throw VideoError(path, "", "is a directory, expected a video file");
    if (::access(path.c_str(), R_OK) != 0) throw VideoError(path, "", "file is not readable (permission denied)");
}

}  // namespace

FileSource::FileSource(FileOptions options) : options_(std::move(options)) {
    const std::string& path = options_.path;
    checkReadable(path);
    // FFmpeg explicitly: OpenCV's GStreamer backend cannot open mp4 here.
    if (!capture_.open(path, cv::CAP_FFMPEG))
        throw VideoError(path, "", "FFmpeg cannot open it: not a video, or an unsupported container or codec");
    info_.width = static_cast<int>(capture_.get(cv::CAP_PROP_FRAME_WIDTH));
    info_.height = static_cast<int>(capture_.get(cv::CAP_PROP_FRAME_HEIGHT));
    info_.fps = capture_.get(cv::CAP_PROP_FPS);
    info_.frameCount = static_cast<std::int64_t>(capture_.get(cv::CAP_PROP_FRAME_COUNT));
    info_.codec = fourccString(static_cast<std::uint32_t>(capture_.get(cv::CAP_PROP_FOURCC)));
    if (!(info_.fps > 0.0 && info_.fps < 1000.0)) {
        spdlog::warn(joinText(path, ": container gives no usable frame rate (", info_.fps, "); assuming 30 fps"));
        info_.fps = 30.0;
    }
    if (!capture_.read(pending_) || pending_.empty())
        throw VideoError(path, "frame 0",
                         joinText("codec '", info_.codec, "' decoded no image: unsupported codec or damaged start"));
    if (info_.width <= 0 || info_.height <= 0) {
        info_.width = pending_.cols;
        info_.height = pending_.rows;
    }
}

std::chrono::nanoseconds FileSource::timestampOf(std::int64_t index) const {
    return loopOffset_ + std::chrono::nanoseconds(std::llround(static_cast<double>(index) * 1e9 / info_.fps));
}

void FileSource::seek(std::int64_t frameIndex) {
    if (frameIndex < 0 || (info_.frameCount > 0 && frameIndex >= info_.frameCount))
        throw VideoError(options_.path, joinText("seek to frame ", frameIndex),
                         joinText("expected 0..", info_.frameCount - 1));
    pending_.release();
    capture_.set(cv::CAP_PROP_POS_FRAMES, static_cast<double>(frameIndex));
    index_ = frameIndex;
    pacer_.reset();
}

// The next decodable image, or nullopt at the true end of the file.
std::optional<cv::Mat> FileSource::decode() {
    cv::Mat img;
    if (!pending_.empty()) {
        img = pending_;
        pending_.release();
        return img;
    }
    while (true) {
        if (capture_.read(img) && !img.empty()) return img;
        // No image before the container's frame count: the file is cut short
        // or damaged here. Past the count, it simply ended.
        if (info_.frameCount <= 0 || index_ >= info_.frameCount) return std::nullopt;
        const std::string where = joinText("frame ", index_, " of ", info_.frameCount);
        if (options_.onDamage == OnDamage::Stop)
            throw VideoError(options_.path, where, "decoder returned no image (truncated or damaged file)");
        spdlog::warn(joinText(options_.path, ": ", where, ": decoder returned no image; skipping (on-damage: skip)"));
        ++skipped_;
        ++index_;
        if (index_ >= info_.frameCount) return std::nullopt;
        capture_.set(cv::CAP_PROP_POS_FRAMES, static_cast<double>(index_));
    }
}

std::optional<Frame> FileSource::next() {
    std::optional<cv::Mat> img = decode();
    if (!img && options_.loop && sequence_ > 0) {
        loopOffset_ = timestampOf(index_);
        capture_.set(cv::CAP_PROP_POS_FRAMES, 0.0);
        index_ = 0;
        img = decode();
    }
    if (!img) return std::nullopt;
    Frame f;
    f.image = std::move(*img);
    f.timestamp = timestampOf(index_);
    f.captured = std::chrono::steady_clock::now();
    f.sequence = sequence_++;
    f.format = PixelFormat::Encoded;
    ++index_;
    return f;
}

GrabResult FileSource::grab() {
    std::optional<Frame> f;
    try {
        f = next();
    } catch (const VideoError& e) {
        return {std::nullopt, {SourceStatus::Error, e.what()}};
    }
    if (!f) {
        std::string reason = joinText(options_.path, ": end after ", sequence_, " frames");
        if (skipped_ > 0) reason += joinText(" (", skipped_, " damaged frames skipped)");
        return {std::nullopt, {SourceStatus::Ended, reason}};
    }
    if (options_.paced) f->captured = pacer_.release(f->timestamp);
    return {std::move(f), {SourceStatus::Streaming, {}}};
}

VideoFileInfo probeVideoFile(const std::string& path) { return FileSource({.path = path}).info(); }

}  // namespace arcomp
