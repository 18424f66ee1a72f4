#pragma once
// Everything wrong with a config file, found in one read. Each issue names
// the place ("station.yaml:12:5") and says what was expected there.
//
// As BadInput it reads as the first issue: source its file, where
// "line 12, column 5" (empty for the file as a whole), reason its message
// with how many more there are. what() lists them all, one a line.

#include "graph/core/BadInput.hpp"

#include <string>
#include <vector>

namespace arcomp {

struct ConfigIssue {
    std::string file;
    int line = 0;    // 1-based; 0 when the file as a whole is meant
    int column = 0;  // 1-based
    std::string message;

    std::string format() const;
};

class ConfigError : public BadInput {
public:
    explicit ConfigError(std::vector<ConfigIssue> issues);
    std::vector<ConfigIssue> issues;
};

}  // namespace arcomp
