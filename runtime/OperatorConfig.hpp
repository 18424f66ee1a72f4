#pragma once
// The config's `status` and `log` sections: how an operator watches a
// station. Without a `status` section there is no HTTP endpoint; without a
// `log` section the station logs to stderr at info level.
//
//   status: {port: 9464}                         # bind defaults to 127.0.0.1
//   status: {port: 9464, bind: 0.0.0.0, token_file: /etc/arcomp/status-token}   # beyond loopback: a token
//   log: {level: debug, file: logs/station.log}  # relative to the config

#include "runtime/StationLog.hpp"
#include "runtime/StatusServer.hpp"

namespace arcomp {

class YamlMap;

struct OperatorConfig {
    bool statusEnabled = false;
    StatusEndpoint status;
    LogSettings log;
};

void readOperatorConfig(YamlMap& root, OperatorConfig& out);

} // namespace arcomp
