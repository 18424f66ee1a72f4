#include "runtime/station/ImageFile.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace arcomp {

namespace fs = std::filesystem;

void writePng(const fs::path& file, const Image& image) {
    std::error_code ec;
    if (file.has_parent_path()) fs::create_directories(file.parent_path(), ec);
    const cv::Mat rgba(image.height, image.width, CV_8UC4, const_cast<std::uint8_t*>(image.rgba.data()));
    cv::Mat bgra;
    cv::cvtColor(rgba, bgra, cv::COLOR_RGBA2BGRA);
    std::vector<std::uint8_t> png;
    try {
        if (!cv::imencode(".png", bgra, png)) throw std::runtime_error("cannot encode " + file.string());
    } catch (const cv::Exception& e) {
        throw std::runtime_error("cannot encode " + file.string() + ": " + e.what());
    }
    // Written beside and renamed, so that a full disk never leaves a
    // half-written image under the final name.
    const fs::path part = file.string() + ".part";
    std::FILE* out = std::fopen(part.c_str(), "wb");
    if (!out) throw std::runtime_error("cannot write " + file.string() + ": " + std::strerror(errno));
    const bool written = std::fwrite(png.data(), 1, png.size(), out) == png.size();
    const int writeErrno = errno;
    const bool closed = std::fclose(out) == 0;
    if (!written || !closed) {
        const int why = written ? errno : writeErrno;
        fs::remove(part, ec);
        throw std::runtime_error("cannot write " + file.string() + ": " + std::strerror(why));
    }
    fs::rename(part, file, ec);
    if (ec) {
        const std::string why = ec.message();
        fs::remove(part, ec);
        throw std::runtime_error("cannot write " + file.string() + ": rename failed: " + why);
    }
}

Image readPng(const fs::path& file) {
    const cv::Mat bgra = cv::imread(file.string(), cv::IMREAD_UNCHANGED);
    if (bgra.empty()) throw std::runtime_error("cannot read image " + file.string());
    cv::Mat rgba;
    if (bgra.channels() == 4)
        cv::cvtColor(bgra, rgba, cv::COLOR_BGRA2RGBA);
    else if (bgra.channels() == 3)
        cv::cvtColor(bgra, rgba, cv::COLOR_BGR2RGBA);
    else
        cv::cvtColor(bgra, rgba, cv::COLOR_GRAY2RGBA);
    Image img;
    img.width = rgba.cols;
    img.height = rgba.rows;
    img.rgba.assign(rgba.data, rgba.data + rgba.total() * 4);
    return img;
}

}  // namespace arcomp
