#include "runtime/ImageFile.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <stdexcept>

namespace arcomp {

namespace fs = std::filesystem;

void writePng(const fs::path& file, const Image& image) {
    std::error_code ec;
    if (file.has_parent_path()) fs::create_directories(file.parent_path(), ec);
    const cv::Mat rgba(image.height, image.width, CV_8UC4, const_cast<std::uint8_t*>(image.rgba.data()));
    cv::Mat bgra;
    cv::cvtColor(rgba, bgra, cv::COLOR_RGBA2BGRA);
    bool ok = false;
    try {
        ok = cv::imwrite(file.string(), bgra);
    } catch (const cv::Exception& e) {
        throw std::runtime_error("cannot write " + file.string() + ": " + e.what());
    }
    if (!ok) throw std::runtime_error("cannot write " + file.string());
}

Image readPng(const fs::path& file) {
    const cv::Mat bgra = cv::imread(file.string(), cv::IMREAD_UNCHANGED);
    if (bgra.empty()) throw std::runtime_error("cannot read image " + file.string());
    cv::Mat rgba;
    if (bgra.channels() == 4) cv::cvtColor(bgra, rgba, cv::COLOR_BGRA2RGBA);
    else if (bgra.channels() == 3) cv::cvtColor(bgra, rgba, cv::COLOR_BGR2RGBA);
    else cv::cvtColor(bgra, rgba, cv::COLOR_GRAY2RGBA);
    Image img;
    img.width = rgba.cols;
    img.height = rgba.rows;
    img.rgba.assign(rgba.data, rgba.data + rgba.total() * 4);
    return img;
}

} // namespace arcomp
