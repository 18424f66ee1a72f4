#include "runtime/config/ConfigError.hpp"

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

std::string sourceOf(const std::vector<ConfigIssue>& issues) { return issues.empty() ? "" : issues.front().file; }

std::string whereOf(const std::vector<ConfigIssue>& issues) {
    if (issues.empty() || issues.front().line == 0) return "";
    return "line " + std::to_string(issues.front().line) + ", column " + std::to_string(issues.front().column);
}

std::string reasonOf(const std::vector<ConfigIssue>& issues) {
    if (issues.empty()) return joined(issues);
    std::string reason = issues.front().message;
    if (issues.size() > 1) reason += " (and " + std::to_string(issues.size() - 1) + " more)";
    return reason;
}

}  // namespace

ConfigError::ConfigError(std::vector<ConfigIssue> list)
    : BadInput(sourceOf(list), whereOf(list), reasonOf(list), joined(list)), issues(std::move(list)) {}

}  // namespace arcomp
