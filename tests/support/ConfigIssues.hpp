#pragma once
// What loading a station config reports, for tests that check its issues:
//
//   auto issues = configIssues(dir.write("station.yaml", text));
//   EXPECT_TRUE(hasIssue(issues, 3, "expected a number")) << describe(issues);

#include "runtime/config/ConfigError.hpp"
#include "runtime/config/StationConfig.hpp"

#include <algorithm>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace arcomp::test {

// The issues loadStationConfig throws for `file`; none when it loads.
inline std::vector<ConfigIssue> configIssues(const std::filesystem::path& file) {
    try {
        loadStationConfig(file);
    } catch (const ConfigError& e) {
        return e.issues;
    }
    return {};
}

// Whether an issue on `line` (and `column`, when given) says `part`.
inline bool hasIssue(const std::vector<ConfigIssue>& issues, int line, const std::string& part,
                     std::optional<int> column = std::nullopt) {
    for (const ConfigIssue& i : issues)
        if (i.line == line && (!column || i.column == *column) && i.message.find(part) != std::string::npos)
            return true;
    return false;
}

// The 1-based line of `text` that first holds `part`; 0 when none does.
inline int lineOf(const std::string& text, const std::string& part) {
    const auto at = text.find(part);
    if (at == std::string::npos) return 0;
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

inline std::string describe(const std::vector<ConfigIssue>& issues) {
    std::string s;
    for (const ConfigIssue& i : issues) s += i.format() + "\n";
    return s;
}

}  // namespace arcomp::test
