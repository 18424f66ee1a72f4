#pragma once
// The operator's window into a running station: an HTTP server on its own
// thread answering GET /status (JSON) and GET /metrics (Prometheus text
// format, so fleets are scraped like any other service). Binds to loopback
// unless the config says otherwise, and beyond loopback answers only
// requests that carry the bearer token (runtime/config/StatusAccess.hpp).
//
//   StatusServer server(metrics, {.bind = "127.0.0.1", .port = 9464});
//   int port = server.port();   // the bound port (useful with port 0)
//
// One thread polls every socket, so idle, slow or hostile clients cost a
// descriptor each, never a worker that a scrape would wait for. The
// connections are bounded in number, in number per client address, and in
// time: a client has `requestTimeout` to send its request head and as long
// again to take the reply, and each connection carries one request. When a
// new connection would pass a bound, the connection that has been idle the
// longest (still waiting for its request) is closed to make room, so a
// scraper that connects is served even while the table is full.
//
// A port that cannot be bound, or a token file that cannot be read, is an
// error with the address or file in the message; the station logs it and
// runs on without a status endpoint.

#include "runtime/config/OperatorConfig.hpp"
#include "runtime/operator/StationMetrics.hpp"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

namespace arcomp {

// What the server has turned away since it started, for the load bench and
// for tests.
struct StatusServerCounters {
    std::uint64_t served = 0;        // 200 replies
    std::uint64_t refused = 0;       // 4xx replies: bad request, unknown path, missing or wrong token
    std::uint64_t unauthorized = 0;  // of those, 401
    std::uint64_t evicted = 0;       // connections closed to keep within the bounds: the idlest, or a
                                     // new one when every slot was mid-reply
    std::uint64_t timedOut = 0;      // closed at the request timeout
};

class StatusServer {
public:
    // Throws std::runtime_error when the address cannot be bound, and
    // BadInput when the token file cannot be used or a non-loopback bind
    // has none.
    StatusServer(const StationMetrics& metrics, const StatusEndpoint& endpoint);
    ~StatusServer();
    StatusServer(const StatusServer&) = delete;
    StatusServer& operator=(const StatusServer&) = delete;

    int port() const { return port_; }
    StatusServerCounters counters() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    int port_ = 0;
};

}  // namespace arcomp
