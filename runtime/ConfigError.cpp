#include "runtime/ConfigError.hpp"

namespace arcomp {

std::string ConfigIssue::format() const {
    if (line == 0) return file + ": " + message;
    return file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message;
}

namespace {
std::string joined(const std::vector<ConfigIssue>& issues) {
    std::string text = std::to_string(issues.size()) + (issues.size() == 1 ? " error" : " errors") + " in config";
    for (const ConfigIssue& i : issues) text += "\n  " + i.format();
    return text;
}
} // namespace

ConfigError::ConfigError(std::vector<ConfigIssue> list) : std::runtime_error(joined(list)), issues(std::move(list)) {}

} // namespace arcomp
