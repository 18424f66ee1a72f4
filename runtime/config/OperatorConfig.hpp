#pragma once
// The config's `status` and `log` sections: how an operator watches a
// station. Without a `status` section there is no HTTP endpoint; without a
// `log` section the station logs to stderr at info level.
//
//   status: {port: 9464}                         # bind defaults to 127.0.0.1
//   status: {port: 9464, bind: 0.0.0.0, token_file: /etc/arcomp/status-token}   # beyond loopback: a token
//   log: {level: debug, file: logs/station.log}  # relative to the config

#include <chrono>
#include <filesystem>
#include <string>

namespace arcomp {

class YamlMap;

// How many connections the status endpoint holds, and for how long
// (runtime/operator/StatusServer.hpp).
struct StatusLimits {
    int maxConnections = 128;
    int maxPerClient = 16;  // per client IP address
    std::chrono::milliseconds requestTimeout{2000};
    bool operator==(const StatusLimits&) const = default;
};

struct StatusEndpoint {
    std::string bind = "127.0.0.1";
    int port = 0;                          // 0: any free port
    std::filesystem::path tokenFile = {};  // required when `bind` is not loopback
    StatusLimits limits = {};
    bool operator==(const StatusEndpoint&) const = default;
};

struct LogSettings {
    std::string level = "info";  // trace, debug, info, warn, error, critical, off
    std::filesystem::path file;  // empty: stderr only
    int maxMegabytes = 10;       // per file
    int files = 5;               // rotated files kept
};

struct OperatorConfig {
    bool statusEnabled = false;
    StatusEndpoint status;
    LogSettings log;
};

void readOperatorConfig(YamlMap& root, OperatorConfig& out);

}  // namespace arcomp
