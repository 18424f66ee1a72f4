#pragma once
// The operator's window into a running station: an HTTP server on its own
// thread answering GET /status (JSON) and GET /metrics (Prometheus text
// format, so fleets are scraped like any other service). Binds to loopback
// unless the config says otherwise.
//
//   StatusServer server(metrics, {.bind = "127.0.0.1", .port = 9464});
//   int port = server.port();   // the bound port (useful with port 0)
//
// A port that cannot be bound is an error with the address in the message;
// the station logs it and runs on without a status endpoint.

#include "runtime/StationMetrics.hpp"

#include <memory>
#include <string>

namespace arcomp {

struct StatusEndpoint {
    std::string bind = "127.0.0.1";
    int port = 0;  // 0: any free port
};

class StatusServer {
public:
    // Throws std::runtime_error when the address cannot be bound.
    StatusServer(const StationMetrics& metrics, const StatusEndpoint& endpoint);
    ~StatusServer();
    StatusServer(const StatusServer&) = delete;
    StatusServer& operator=(const StatusServer&) = delete;

    int port() const { return port_; }

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    int port_ = 0;
};

} // namespace arcomp
