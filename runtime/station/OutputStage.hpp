#pragma once
// The frame's files: the composited frame as numbered PNGs and/or one video
// file, and the matte's alpha as numbered PNGs for inspection. On a GPU the
// frame is read back asynchronously (FrameReadback): its files are written
// one call later, and finish() writes the last. A write that
// fails (a full disk, a folder gone read-only) is counted and kept for the
// operator, not thrown: the kiosk goes on showing its frames, and frames
// written before stay whole (PNGs are written beside and renamed).
//
//   OutputStage out(cfg.compositing.output, capture.fps(), size);   // opens the video file
//   out.write(compositor.output(), matte.person());                  // once a frame
//   out.finish();                                                    // closes the video file

#include "runtime/config/CompositingConfig.hpp"
#include "runtime/gl/FrameReadback.hpp"
#include "runtime/gl/RenderTarget.hpp"
#include "video/sources/VideoFileWriter.hpp"

#include <glm/glm.hpp>
#include <opencv2/core/mat.hpp>

#include <cstdint>
#include <memory>
#include <string>

namespace arcomp {

class OutputStage {
public:
    // Throws VideoError when the video file cannot be opened.
    OutputStage(const OutputConfig& config, double fps, glm::ivec2 size,
                FrameReadback::Mode readback = FrameReadback::Mode::Auto);

    // Files are numbered from here: a reloaded station continues where the
    // previous one stopped instead of overwriting its frames.
    void setFirstIndex(std::uint64_t index) { next_ = index; }
    void write(const RenderTarget& frame, const cv::Mat& person);
    // Writes the frame still being read back and closes the video file.
    // Safe to call twice; never throws (a failure is counted).
    void finish();

    std::uint64_t failures() const { return failures_; }
    const std::string& lastError() const { return lastError_; }

private:
    void writeMatte(std::uint64_t index, const cv::Mat& person);
    void writeFrame(std::uint64_t index, const Image& image);
    template <class Step>
    void counted(Step&& step);

    OutputConfig config_;
    std::unique_ptr<VideoFileWriter> video_;
    FrameReadback readback_;
    std::uint64_t inFlight_ = 0;  // the index of the frame readback_ holds
    Image image_;                 // the frame read back, kept so that its 8 MB (at 1080p) are not allocated again
    cv::Mat bgr_;
    std::uint64_t next_ = 0;
    std::uint64_t failures_ = 0;
    std::string lastError_;
};

}  // namespace arcomp
