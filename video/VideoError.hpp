#pragma once
// A video input that cannot be used: what() reads
// "<source>: <where>: <reason>", e.g.
// "clips/a.avi: frame 287 of 795: decoder returned no image (truncated or damaged)".

#include <stdexcept>
#include <string>

namespace arcomp {

class VideoError : public std::runtime_error {
public:
    VideoError(std::string source, std::string where, std::string reason)
        : std::runtime_error(source + ": " + (where.empty() ? "" : where + ": ") + reason),
          source(std::move(source)), where(std::move(where)), reason(std::move(reason)) {}

    std::string source;
    std::string where;
    std::string reason;
};

} // namespace arcomp
