#include "runtime/config/ShowControlConfig.hpp"

#include "runtime/config/YamlMap.hpp"

#include <charconv>

namespace arcomp {
namespace {

// "host:port" entries; a bad one is reported at its own line and left out.
std::vector<NetworkTarget> readTargets(YamlMap& section) {
    std::vector<NetworkTarget> out;
    const std::string key = section.where() + ".targets";
    const YAML::Node list = section.take("targets");
    if (!list) {
        section.report().add(section.mark(), key + ": required, a list of \"host:port\"");
        return out;
    }
    if (!list.IsSequence()) {
        section.report().add(list.Mark(), key + ": expected a list of \"host:port\"");
        return out;
    }
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string where = key + "[" + std::to_string(i) + "]";
        const YAML::Node item = list[i];
        const std::string text = item.IsScalar() ? item.Scalar() : std::string();
        const std::size_t colon = text.rfind(':');
        int port = 0;
        const char* portEnd = text.data() + text.size();
        const bool numeric = colon != std::string::npos &&
                             std::from_chars(text.data() + colon + 1, portEnd, port).ptr == portEnd &&
                             colon + 1 < text.size();
        if (!numeric || colon == 0 || port < 1 || port > 65535) {
            section.report().add(item.Mark(), where + ": '" + text +
                                                  "' is not a target; expected \"host:port\" with a port 1-65535, "
                                                  "e.g. \"127.0.0.1:9000\"");
            continue;
        }
        std::string host = text.substr(0, colon);
        if (host.size() > 2 && host.front() == '[' && host.back() == ']')
            host = host.substr(1, host.size() - 2);  // IPv6
        out.push_back({.host = host, .port = port, .where = where});
    }
    return out;
}

}  // namespace

void readShowControlConfig(YamlMap& root, ShowControlConfig& out) {
    if (!root.has("show_control")) return;
    YamlMap show = root.map("show_control");
    if (show.has("osc")) {
        YamlMap osc = show.map("osc");
        out.osc.targets = readTargets(osc);
        osc.finish();
    }
    if (show.has("tuio")) {
        YamlMap tuio = show.map("tuio");
        out.tuio.targets = readTargets(tuio);
        if (tuio.has("floor")) {
            YamlMap floor = tuio.map("floor");
            std::vector<float> min, max;
            floor.numbers("min", min, -1e4, 1e4, Required::Yes);
            floor.numbers("max", max, -1e4, 1e4, Required::Yes);
            if (min.size() != 2 || max.size() != 2) {
                if (!min.empty() || !max.empty())
                    floor.report().add(floor.mark(), floor.where() + ": min and max are [x, z], two numbers each");
            } else if (max[0] <= min[0] || max[1] <= min[1]) {
                floor.report().add(floor.mark(), floor.where() + ": max must exceed min in x and in z");
            } else {
                out.tuio.floorMin = {min[0], min[1]};
                out.tuio.floorMax = {max[0], max[1]};
            }
            floor.finish();
        }
        tuio.finish();
    }
    show.finish();
}

}  // namespace arcomp
