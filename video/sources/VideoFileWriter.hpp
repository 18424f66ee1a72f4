#pragma once
// Writes frames to a video file through OpenCV's FFmpeg backend, and
// finishes the file properly (header, index) on close() or destruction, so
// that a station stopped between frames leaves a playable file.
//
//   VideoFileWriter out("out/demo.avi", "MJPG", 25.0, {768, 576});  // throws VideoError
//   out.write(bgr);    // CV_8UC3 of that size
//   out.close();

#include <opencv2/core/mat.hpp>
#include <opencv2/videoio.hpp>

#include <cstdint>
#include <string>

namespace arcomp {

class VideoFileWriter {
public:
    VideoFileWriter(std::string path, const std::string& fourcc, double fps, cv::Size size);
    ~VideoFileWriter();
    VideoFileWriter(const VideoFileWriter&) = delete;
    VideoFileWriter& operator=(const VideoFileWriter&) = delete;

    void write(const cv::Mat& bgr);
    void close();
    std::uint64_t framesWritten() const { return frames_; }
    const std::string& path() const { return path_; }

private:
    std::string path_;
    cv::Size size_;
    cv::VideoWriter writer_;
    std::uint64_t frames_ = 0;
};

}  // namespace arcomp
