#include "video/streams/H264Recording.hpp"

#include <algorithm>
#include <cctype>

namespace arcomp {

namespace {

std::string lowerExtension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

}  // namespace

bool isH264Container(const std::filesystem::path& path) {
    const std::string e = lowerExtension(path);
    return e == ".mp4" || e == ".m4v" || e == ".mov" || e == ".mkv";
}

std::unique_ptr<H264Pipeline> openH264Recording(const std::filesystem::path& path, H264Settings settings,
                                                RawVideo input, WhenFull whenFull) {
    std::error_code ec;
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ec);
    // A file is watched later, not joined live: lookahead and B-frames are
    // worth their delay.
    settings.lowLatency = false;
    const ElementSpec muxer = lowerExtension(path) == ".mkv" ? ElementSpec{"matroskamux"}
                                                             : ElementSpec{"mp4mux", {{"fragment-duration", "1000"}}};
    return std::make_unique<H264Pipeline>(path.string(), settings, input,
                                          std::vector<ElementSpec>{muxer, {"filesink", {{"location", path.string()}}}},
                                          whenFull, 30);
}

}  // namespace arcomp
