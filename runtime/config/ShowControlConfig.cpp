#include "runtime/config/ShowControlConfig.hpp"

#include "runtime/config/StatusAccess.hpp"
#include "runtime/config/YamlMap.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>

#include <charconv>
#include <optional>

namespace arcomp {
namespace {

// "host:port", or none with the problem reported at `mark`.
std::optional<NetworkTarget> parseTarget(const std::string& text, const std::string& where, const YAML::Mark& mark,
                                         ConfigReport& report) {
    const std::size_t colon = text.rfind(':');
    int port = 0;
    const char* portEnd = text.data() + text.size();
    const bool numeric = colon != std::string::npos && colon + 1 < text.size() &&
                         std::from_chars(text.data() + colon + 1, portEnd, port).ptr == portEnd;
    if (!numeric || colon == 0 || port < 1 || port > 65535) {
        report.add(mark, where + ": '" + text +
                             "' is not a target; expected \"host:port\" with a port 1-65535, e.g. \"127.0.0.1:9000\"");
        return std::nullopt;
    }
    std::string host = text.substr(0, colon);
    if (host.size() > 2 && host.front() == '[' && host.back() == ']') host = host.substr(1, host.size() - 2);  // IPv6
    return NetworkTarget{.host = host, .port = port, .where = where};
}

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
        if (!item.IsScalar()) {
            section.report().add(item.Mark(),
                                 where + ": expected \"host:port\" as one string, e.g. \"127.0.0.1:9000\"");
            continue;
        }
        const std::string text = item.Scalar();
        if (auto target = parseTarget(text, where, item.Mark(), section.report())) out.push_back(*target);
    }
    return out;
}

void readMqtt(YamlMap& mqtt, MqttOutputConfig& out) {
    out.enabled = true;
    std::string broker;
    mqtt.text("broker", broker, Required::Yes);
    if (!broker.empty())
        if (auto target = parseTarget(broker, mqtt.where() + ".broker", mqtt.mark(), mqtt.report()))
            out.broker = *target;
    mqtt.text("topic_prefix", out.topicPrefix);
    if (out.topicPrefix.empty() || out.topicPrefix.find_first_of("+#") != std::string::npos ||
        out.topicPrefix.front() == '/' || out.topicPrefix.back() == '/')
        mqtt.report().add(mqtt.mark(), mqtt.where() + ".topic_prefix: '" + out.topicPrefix +
                                           "' cannot start a topic; expected levels without '+', '#' or a "
                                           "leading or trailing '/', e.g. arcomp/entrance");
    mqtt.text("client_id", out.clientId);
    mqtt.number("rate_hz", out.rateHz, 0.1, 100.0);
    mqtt.integer("keepalive_s", out.keepaliveSeconds, 5, 3600);
    mqtt.integer("event_queue", out.eventQueue, 1, 1000000);
    mqtt.path("username_file", out.usernameFile, true);
    mqtt.path("password_file", out.passwordFile, true);
    if (out.usernameFile.empty() != out.passwordFile.empty())
        mqtt.report().add(mqtt.mark(), mqtt.where() + ": username_file and password_file come together");
    if (mqtt.has("tls")) {
        YamlMap tls = mqtt.map("tls");
        tls.path("ca_file", out.caFile, true, Required::Yes);
        tls.path("cert_file", out.certFile, true);
        tls.path("key_file", out.keyFile, true);
        if (out.certFile.empty() != out.keyFile.empty())
            tls.report().add(tls.mark(), tls.where() + ": cert_file and key_file come together");
        tls.finish();
    }
    mqtt.finish();
}

void readCues(YamlMap& cues, bool mqttBroker, CueInputConfig& out) {
    ConfigReport& report = cues.report();
    if (cues.has("osc")) {
        YamlMap osc = cues.map("osc");
        out.osc = true;
        std::string listen;
        osc.text("listen", listen, Required::Yes);
        // A port alone listens on loopback.
        if (!listen.empty() && listen.find(':') == std::string::npos) listen = "127.0.0.1:" + listen;
        if (!listen.empty())
            if (auto target = parseTarget(listen, osc.where() + ".listen", osc.mark(), report)) out.listen = *target;
        if (osc.has("allow")) {
            const YAML::Node list = osc.take("allow");
            if (!list.IsSequence()) report.add(list.Mark(), osc.where() + ".allow: expected a list of IPv4 addresses");
            for (std::size_t i = 0; list.IsSequence() && i < list.size(); ++i) {
                in_addr parsed{};
                const std::string text = list[i].IsScalar() ? list[i].Scalar() : "";
                if (inet_pton(AF_INET, text.c_str(), &parsed) != 1)
                    report.add(list[i].Mark(), osc.where() + ".allow[" + std::to_string(i) + "]: '" + text +
                                                   "' is not an IPv4 address such as 10.0.0.5");
                else
                    out.allow.push_back(text);
            }
        }
        if (!isLoopbackAddress(out.listen.host) && out.allow.empty())
            report.add(osc.mark(), osc.where() + ": listening on '" + out.listen.host +
                                       "', beyond loopback, needs allow: the senders' IPv4 addresses (OSC has no "
                                       "credentials; only listed senders are heard)");
        osc.finish();
    }
    cues.boolean("mqtt", out.mqtt);
    if (out.mqtt && !mqttBroker)
        report.add(cues.mark(), cues.where() + ".mqtt: needs show_control.mqtt, the broker to take cues from");
    out.snapshotFolder = "snapshots";
    cues.path("snapshot_folder", out.snapshotFolder, false);
    if (out.snapshotFolder.is_relative()) out.snapshotFolder = report.file().parent_path() / out.snapshotFolder;
    cues.finish();
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
    if (show.has("mqtt")) {
        YamlMap mqtt = show.map("mqtt");
        readMqtt(mqtt, out.mqtt);
    }
    if (show.has("cues")) {
        YamlMap cues = show.map("cues");
        readCues(cues, out.mqtt.enabled, out.cues);
    }
    show.finish();
}

}  // namespace arcomp
