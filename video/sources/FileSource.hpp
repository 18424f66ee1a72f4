#pragma once
// A video file as a frame source, decoded by OpenCV's FFmpeg backend. Replay
// calls next() for frame 0, 1, 2, ... with no thread and no drops, so two
// runs see identical pixels; a station wraps it in a CaptureThread with
// `paced` set to play at the file's own rate.
//
//   FileSource file({.path = "clips/people.avi", .onDamage = OnDamage::Skip});
//   while (std::optional<Frame> f = file.next()) write(*f);   // nullopt at the end
//
// Timestamps are frame index / fps on the file's timeline (continuing across
// loops). OpenCV's CAP_PROP_POS_MSEC is not used: it reads 0 after the last
// frame. Damage mid-file (the decoder yields no image before the frame count
// says the file ends) throws VideoError naming the file and frame, or with
// OnDamage::Skip is logged and stepped over.

#include "video/sources/FrameGrabber.hpp"
#include "video/sources/FramePacer.hpp"

#include <opencv2/videoio.hpp>

#include <cstdint>
#include <string>

namespace arcomp {

enum class OnDamage { Stop, Skip };

struct FileOptions {
    std::string path;
    bool paced = false;  // grab() waits until each frame is due; next() never waits
    bool loop = false;
    OnDamage onDamage = OnDamage::Stop;
};

struct VideoFileInfo {
    std::string codec;  // fourcc as text, e.g. "FMP4", "MJPG", "H264"
    int width = 0;
    int height = 0;
    double fps = 0.0;
    std::int64_t frameCount = 0;  // as the container claims; damage may end the file earlier
};

class FileSource : public FrameGrabber {
public:
    // Throws VideoError when the file is missing, unreadable, not a video,
    // or in a codec FFmpeg cannot decode.
    explicit FileSource(FileOptions options);

    std::optional<Frame> next();
    void seek(std::int64_t frameIndex);
    GrabResult grab() override;
    std::string name() const override { return options_.path; }

    const VideoFileInfo& info() const { return info_; }
    std::uint64_t damagedFramesSkipped() const { return skipped_; }

private:
    std::optional<cv::Mat> decode();
    std::chrono::nanoseconds timestampOf(std::int64_t index) const;

    FileOptions options_;
    cv::VideoCapture capture_;
    VideoFileInfo info_;
    cv::Mat pending_;             // frame 0, decoded when opening to prove the codec works
    std::int64_t index_ = 0;      // the next frame of the file to decode
    std::uint64_t sequence_ = 0;  // frames handed out, across loops
    std::chrono::nanoseconds loopOffset_{0};
    std::uint64_t skipped_ = 0;
    FramePacer pacer_;
};

// Reads a file's container facts without decoding more than one frame.
VideoFileInfo probeVideoFile(const std::string& path);

}  // namespace arcomp
