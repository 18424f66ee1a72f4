#pragma once
// A model that cannot be used safely. what() reads
// "<file>: <where>: <reason>", where `where` is a JSON pointer for glTF
// ("/accessors/3/bufferView") or "line N" for OBJ.

#include "graph/core/BadInput.hpp"

#include <string>

namespace arcomp {

class ModelError : public BadInput {
public:
    ModelError(std::string file_, std::string where_, std::string reason_)
        : BadInput(std::move(file_), std::move(where_), std::move(reason_)), file(source) {}

    std::string file;  // the same as source: the name model code has always used
};

}  // namespace arcomp
