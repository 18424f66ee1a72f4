#pragma once
// The frame's outputs: the composited frame as numbered PNGs and/or one video
// file, and the matte's alpha as numbered PNGs for inspection. A video file
// in MP4 or Matroska is H.264 through GStreamer (H264Recording): encoded on
// GStreamer's threads; live, a frame the encoder has no room for is dropped
// and counted (recordingDrops()) rather than waited for, while a replay
// (WhenFull::Wait) keeps every frame. Streams (SRT) get the same frame and
// never wait, in replay either: a receiver is not a file (StreamOutputs). On a GPU the
// frame is read back asynchronously (FrameReadback): its files are written
// one call later, and finish() writes the last. A write that
// fails (a full disk, a folder gone read-only) is counted and kept for the
// operator, not thrown: the kiosk goes on showing its frames, and frames
// written before stay whole (PNGs are written beside and renamed).
//
//   OutputStage out(cfg.compositing.output, capture.fps(), size);   // opens the video file
//   out.write(compositor.output(), matte.person());                  // once a frame
//   out.finish();                                                    // closes the video file
//
// A trigger or a cue asks for a snapshot (the next frame written, as
// snapshot-NNNNNN.png in a folder) or a clip (the next frames for some
// seconds, as clip-NNNNNN.avi through the same video writer); both are
// numbered by the frame they start on, and fail as any file does: counted.

#include "runtime/config/CompositingConfig.hpp"
#include "runtime/gl/FrameReadback.hpp"
#include "runtime/gl/RenderTarget.hpp"
#include "video/sources/VideoFileWriter.hpp"
#include "video/streams/H264Pipeline.hpp"
#include "video/streams/StreamOutputs.hpp"

#include <glm/glm.hpp>
#include <opencv2/core/mat.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace arcomp {

class OutputStage {
public:
    // Throws VideoError when the video file cannot be opened.
    OutputStage(const OutputConfig& config, double fps, glm::ivec2 size,
                FrameReadback::Mode readback = FrameReadback::Mode::Auto, WhenFull recording = WhenFull::Drop);

    // What only this machine can say about the outputs: an H.264 recording
    // or a stream without any encoder, a stream's GStreamer element
    // missing. Throws BadInput naming the config's place and the package
    // to install.
    static void preflight(const OutputConfig& config);

    // Files are numbered from here: a reloaded station continues where the
    // previous one stopped instead of overwriting its frames.
    void setFirstIndex(std::uint64_t index) { next_ = index; }
    void write(const RenderTarget& frame, const cv::Mat& person);
    // From the next write() on.
    void snapshot(const std::filesystem::path& folder);
    void clip(const std::filesystem::path& folder, double seconds);
    std::uint64_t snapshotsWritten() const { return snapshotsWritten_; }
    std::uint64_t clipsWritten() const { return clipsWritten_; }
    // Writes the frame still being read back and closes the video file.
    // Safe to call twice; never throws (a failure is counted).
    void finish();

    std::uint64_t failures() const { return failures_; }
    // Frames the H.264 recording had no room for; 0 without one.
    std::uint64_t recordingDrops() const { return recording_ ? recording_->dropped() : 0; }
    // Each stream's state and counts (output.streams); empty without any.
    std::vector<StreamStatus> streamStatus() const;
    const std::string& lastError() const { return lastError_; }

private:
    void writeMatte(std::uint64_t index, const cv::Mat& person);
    void writeFrame(std::uint64_t index, const Image& image);
    void writeRequested(std::uint64_t index, const Image& image);
    void record(const Image& image);
    void noteRecordingFailure();
    template <class Step>
    void counted(Step&& step);

    struct Snapshot {
        std::uint64_t index;
        std::filesystem::path folder;
    };
    struct Clip {
        std::uint64_t index;
        std::filesystem::path folder;
        std::uint64_t frames;                   // still to write
        std::unique_ptr<VideoFileWriter> file;  // opened with its first frame
    };

    OutputConfig config_;
    std::unique_ptr<VideoFileWriter> video_;
    std::unique_ptr<H264Pipeline> recording_;
    std::unique_ptr<StreamOutputs> streams_;
    bool recordingFailureCounted_ = false;
    FrameReadback readback_;
    std::uint64_t inFlight_ = 0;  // the index of the frame readback_ holds
    Image image_;                 // the frame read back, kept so that its 8 MB (at 1080p) are not allocated again
    cv::Mat bgr_;
    double fps_;
    glm::ivec2 size_;
    std::vector<Snapshot> snapshots_;
    std::vector<Clip> clips_;
    std::uint64_t snapshotsWritten_ = 0, clipsWritten_ = 0;
    std::uint64_t next_ = 0;
    std::uint64_t failures_ = 0;
    std::string lastError_;
};

}  // namespace arcomp
