#pragma once
// Input that cannot be used: a file, device or stream, or a value the user
// gave. Every such error derives from BadInput, so that whoever decides
// "the user's fault or ours" (arcomp exits 2 for bad input, 1 otherwise)
// catches one type:
//
//   try { loadModel(path, scene, scene.root()); }
//   catch (const BadInput& e) {   // ModelError, VideoError, ConfigError, ...
//       log(e.source, e.where, e.reason);
//   }
//
// what() reads "<source>: <where>: <reason>", an empty part left out with
// its separator, e.g. "clips/a.avi: frame 287 of 795: decoder returned no
// image". A subclass with an established text of its own (ConfigError lists
// every issue) keeps it through the protected constructor; the three parts
// are there either way.
//
// Header-only and free of scene types, so that video/ can throw it too.

#include <stdexcept>
#include <string>
#include <utility>

namespace arcomp {

class BadInput : public std::runtime_error {
public:
    // The base is built first, so the parts are read before they move.
    BadInput(std::string source_, std::string where_, std::string reason_)
        : std::runtime_error(formatted(source_, where_, reason_)), source(std::move(source_)), where(std::move(where_)),
          reason(std::move(reason_)) {}

    std::string source;  // the file, device or stream; may be empty (a command-line value)
    std::string where;   // a JSON pointer, "line 12", "frame 287 of 795"; empty for the whole source
    std::string reason;  // what is wrong there

protected:
    BadInput(std::string source_, std::string where_, std::string reason_, std::string message)
        : std::runtime_error(std::move(message)), source(std::move(source_)), where(std::move(where_)),
          reason(std::move(reason_)) {}

private:
    static std::string formatted(const std::string& source, const std::string& where, const std::string& reason) {
        std::string text;
        if (!source.empty()) text += source + ": ";
        if (!where.empty()) text += where + ": ";
        return text + reason;
    }
};

}  // namespace arcomp
