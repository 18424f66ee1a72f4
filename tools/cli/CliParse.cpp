#include "tools/cli/CliParse.hpp"

#include "tools/cli/Command.hpp"

#include <charconv>
#include <cmath>

namespace arcomp {

namespace {
bool parseFloat(std::string_view s, float& out) {
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && end == s.data() + s.size() && std::isfinite(out);
}
}  // namespace

glm::ivec2 parseSize(const std::string& text, const std::string& option) {
    const auto x = text.find('x');
    int w = 0, h = 0;
    if (x != std::string::npos) {
        const auto [e1, ec1] = std::from_chars(text.data(), text.data() + x, w);
        const auto [e2, ec2] = std::from_chars(text.data() + x + 1, text.data() + text.size(), h);
        if (ec1 == std::errc() && ec2 == std::errc() && e1 == text.data() + x && e2 == text.data() + text.size() &&
            w > 0 && h > 0 && w <= 16384 && h <= 16384)
            return {w, h};
    }
    throw InputError(option + " '" + text + "': expected WIDTHxHEIGHT, each 1..16384, e.g. 640x480");
}

glm::vec3 parseVec3(const std::string& text, const std::string& option) {
    glm::vec3 v;
    std::size_t start = 0;
    for (int i = 0; i < 3; ++i) {
        const auto comma = text.find(',', start);
        const bool last = i == 2;
        if ((comma == std::string::npos) != last ||
            !parseFloat(std::string_view(text).substr(start, comma - start), v[i]))
            throw InputError(option + " '" + text + "': expected three numbers X,Y,Z, e.g. 0,1.5,4");
        start = comma + 1;
    }
    return v;
}

TimerMode parseTimerMode(const std::string& text, const std::string& option) {
    if (text == "finish") return TimerMode::Finish;
    if (text == "cpu") return TimerMode::ProcessCpu;
    if (text == "query") return TimerMode::Query;
    if (text == "auto") return TimerMode::Auto;
    throw InputError(option + " '" + text + "': expected finish, cpu, query or auto");
}

}  // namespace arcomp
