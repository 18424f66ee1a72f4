#include "runtime/config/OperatorConfig.hpp"

#include "graph/core/BadInput.hpp"
#include "runtime/config/StatusAccess.hpp"
#include "runtime/config/YamlMap.hpp"

#include <arpa/inet.h>

namespace arcomp {

void readOperatorConfig(YamlMap& root, OperatorConfig& out) {
    if (root.has("status")) {
        YamlMap status = root.map("status");
        out.statusEnabled = true;
        status.integer("port", out.status.port, 1, 65535, Required::Yes);
        status.text("bind", out.status.bind);
        status.path("token_file", out.status.tokenFile, true);
        if (!isLoopbackAddress(out.status.bind)) {
            in_addr address{};
            if (inet_pton(AF_INET, out.status.bind.c_str(), &address) != 1)
                status.report().add(
                    status.mark(),
                    "status.bind: expected an IPv4 address such as 127.0.0.1 (loopback) or 0.0.0.0 (every interface)");
            else if (out.status.tokenFile.empty())
                status.report().add(status.mark(),
                                    "status.bind: " + out.status.bind +
                                        " is beyond loopback, so the endpoint needs status.token_file: a file "
                                        "holding the bearer token that scrapers must send");
        }
        if (!out.status.tokenFile.empty() && std::filesystem::exists(out.status.tokenFile)) {
            try {
                readBearerToken(out.status.tokenFile);
            } catch (const BadInput& e) {
                status.report().add(status.mark(), "status.token_file: " + std::string(e.what()));
            }
        }
        status.finish();
    }
    YamlMap log = root.map("log");
    log.choice("level", out.log.level, {"trace", "debug", "info", "warn", "error", "critical", "off"});
    log.path("file", out.log.file, false);
    log.integer("max_mb", out.log.maxMegabytes, 1, 4096);
    log.integer("files", out.log.files, 1, 100);
    log.finish();
}

}  // namespace arcomp
