#pragma once
// Everything wrong with a config file, found in one read. Each issue names
// the place ("station.yaml:12:5") and says what was expected there.

#include <stdexcept>
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

class ConfigError : public std::runtime_error {
public:
    explicit ConfigError(std::vector<ConfigIssue> issues);
    std::vector<ConfigIssue> issues;
};

} // namespace arcomp
