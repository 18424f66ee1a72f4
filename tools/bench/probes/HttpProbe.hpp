#pragma once
// A bare TCP/HTTP client for the status endpoint's load bench and tests:
// connections from a chosen loopback source address (127.0.0.0/8 is all
// loopback on Linux, so one machine can play many clients), and one GET
// with a deadline that never blocks longer.
//
//   FileDescriptor idle = connectLoopback(port, "127.0.0.7");   // holds a slot, sends nothing
//   HttpProbeReply r = httpGet(port, "/metrics", {.timeout = 1s});
//   if (r.status == 200) ...

#include "runtime/operator/FileDescriptor.hpp"

#include <chrono>
#include <string>

namespace arcomp {

// A non-blocking socket connected (or connecting) to 127.0.0.1:port from
// `from` (any port). Throws std::runtime_error when the socket cannot be
// made.
FileDescriptor connectLoopback(int port, const std::string& from = "127.0.0.1");

struct HttpProbeRequest {
    std::string from = "127.0.0.1";
    std::string extraHeaders = {};  // whole lines, each ending in \r\n
    std::chrono::milliseconds timeout{1000};
};

struct HttpProbeReply {
    int status = 0;     // 0: no reply within the timeout, or the connection failed
    std::string error;  // why status is 0
    std::string head;
    std::string body;
};

HttpProbeReply httpGet(int port, const std::string& path, const HttpProbeRequest& request = {});

}  // namespace arcomp
