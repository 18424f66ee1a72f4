#pragma once
// One UDP destination, resolved once when made, sent to without ever
// blocking the frame: a datagram the socket cannot take now is dropped,
// and the caller counts it.
//
//   UdpSender osc({.host = "127.0.0.1", .port = 9000, .where = "show_control.osc.targets[0]"});
//   if (!osc.send(bytes)) ++dropped;

#include "runtime/config/ShowControlConfig.hpp"

#include <sys/socket.h>

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>

namespace arcomp {

// A target that cannot be sent to at all (its host does not resolve, no socket).
struct ShowControlError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class UdpSender {
public:
    // Resolves the host (a name may take the resolver's time: at start, not
    // on a frame). Throws ShowControlError naming the target and its config key.
    explicit UdpSender(const NetworkTarget& target);
    ~UdpSender();
    UdpSender(UdpSender&& other) noexcept;
    UdpSender& operator=(UdpSender&&) = delete;
    UdpSender(const UdpSender&) = delete;
    UdpSender& operator=(const UdpSender&) = delete;

    // False when the datagram was not sent (the socket's buffer is full, the
    // network is unreachable); lastError() says why.
    bool send(std::span<const std::uint8_t> datagram);
    const std::string& lastError() const { return lastError_; }

private:
    int fd_ = -1;
    sockaddr_storage address_{};
    socklen_t addressLength_ = 0;
    std::string lastError_;
};

}  // namespace arcomp
