#pragma once
// Text joined from its pieces with the stream operators, for log lines and
// error messages:
//
//   spdlog::info(joinText("holdout of '", name, "': ", note));
//   throw VideoError(path, joinText("frame ", index, " of ", count), "decoder returned no image");
//
// rather than spdlog's "{}" or fmt::format: those instantiate fmt's
// formatter in every file that calls them, about 13 s of build a file under
// the sanitizers, against about 1 s for a ready string.

#include <sstream>
#include <string>

namespace arcomp {

template <class... Parts>
std::string joinText(const Parts&... parts) {
    std::ostringstream out;
    (out << ... << parts);
    return out.str();
}

}  // namespace arcomp
