#pragma once
// A model that cannot be used safely. what() reads
// "<file>: <where>: <reason>", where `where` is a JSON pointer for glTF
// ("/accessors/3/bufferView") or "line N" for OBJ.

#include <stdexcept>
#include <string>

namespace arcomp {

class ModelError : public std::runtime_error {
public:
    ModelError(std::string file, std::string where, std::string reason)
        : std::runtime_error(file + ": " + (where.empty() ? "" : where + ": ") + reason),
          file(std::move(file)), where(std::move(where)), reason(std::move(reason)) {}

    std::string file;
    std::string where;
    std::string reason;
};

} // namespace arcomp
