#include "video/sources/VideoFileWriter.hpp"

#include "video/pixels/VideoError.hpp"

#include <filesystem>

namespace arcomp {

VideoFileWriter::VideoFileWriter(std::string path, const std::string& fourcc, double fps, cv::Size size)
    : path_(std::move(path)), size_(size) {
    if (fourcc.size() != 4) throw VideoError(path_, "writer", "fourcc must have 4 characters, got '" + fourcc + "'");
    std::error_code ec;
    const std::filesystem::path parent = std::filesystem::path(path_).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent, ec);
    const int code = cv::VideoWriter::fourcc(fourcc[0], fourcc[1], fourcc[2], fourcc[3]);
    if (!writer_.open(path_, cv::CAP_FFMPEG, code, fps, size_, true))
        throw VideoError(path_, "writer",
                         "cannot open for writing with codec " + fourcc + " (folder writable? codec known?)");
}

VideoFileWriter::~VideoFileWriter() { close(); }

void VideoFileWriter::write(const cv::Mat& bgr) {
    if (!writer_.isOpened()) throw VideoError(path_, "frame " + std::to_string(frames_), "writer already closed");
    if (bgr.size() != size_ || bgr.type() != CV_8UC3)
        throw VideoError(path_, "frame " + std::to_string(frames_),
                         "expected a BGR image of the size the file was opened with");
    writer_.write(bgr);
    ++frames_;
}

void VideoFileWriter::close() {
    if (writer_.isOpened()) writer_.release();
}

}  // namespace arcomp
