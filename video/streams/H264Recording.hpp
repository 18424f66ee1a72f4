#pragma once
// A recording that plays anywhere: H.264 in MP4 (fragmented: a fragment a
// second, so the file is readable while it is written and keeps what was
// written if the station dies) or in Matroska, by the file's extension.
//
//   if (isH264Container(path))
//       auto file = openH264Recording(path, {}, {768, 576, 25.0}, WhenFull::Drop);

#include "video/streams/H264Pipeline.hpp"

#include <filesystem>
#include <memory>

namespace arcomp {

// .mp4, .m4v, .mov or .mkv (any case).
bool isH264Container(const std::filesystem::path& path);

// Creates missing folders. Throws VideoError naming the file when it cannot
// be written or an element is missing.
std::unique_ptr<H264Pipeline> openH264Recording(const std::filesystem::path& path, H264Settings settings,
                                                RawVideo input, WhenFull whenFull);

}  // namespace arcomp
