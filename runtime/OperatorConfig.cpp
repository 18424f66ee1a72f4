#include "runtime/OperatorConfig.hpp"

#include "runtime/YamlMap.hpp"

#include <arpa/inet.h>

namespace arcomp {

void readOperatorConfig(YamlMap& root, OperatorConfig& out) {
    if (root.has("status")) {
        YamlMap status = root.map("status");
        out.statusEnabled = true;
        status.integer("port", out.status.port, 1, 65535, Required::Yes);
        status.text("bind", out.status.bind);
        in_addr address{};
        if (inet_pton(AF_INET, out.status.bind.c_str(), &address) != 1)
            status.report().add(status.mark(), "status.bind: expected an IPv4 address such as 127.0.0.1 (loopback) or 0.0.0.0 (every interface)");
        status.finish();
    }
    YamlMap log = root.map("log");
    log.choice("level", out.log.level, {"trace", "debug", "info", "warn", "error", "critical", "off"});
    log.path("file", out.log.file, false);
    log.integer("max_mb", out.log.maxMegabytes, 1, 4096);
    log.integer("files", out.log.files, 1, 100);
    log.finish();
}

} // namespace arcomp
