#include "runtime/showcontrol/UdpSender.hpp"

#include <netdb.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

namespace arcomp {

UdpSender::UdpSender(const NetworkTarget& target) {
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_DGRAM;
    addrinfo* found = nullptr;
    const std::string port = std::to_string(target.port);
    if (const int e = getaddrinfo(target.host.c_str(), port.c_str(), &hints, &found); e != 0)
        throw ShowControlError(target.where + ": host '" + target.host + "' does not resolve (" + gai_strerror(e) +
                               ")");
    std::memcpy(&address_, found->ai_addr, found->ai_addrlen);
    addressLength_ = found->ai_addrlen;
    fd_ = socket(found->ai_family, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    freeaddrinfo(found);
    if (fd_ < 0)
        throw ShowControlError(target.where + ": no UDP socket for " + target.text() + " (" + std::strerror(errno) +
                               ")");
}

UdpSender::~UdpSender() {
    if (fd_ >= 0) close(fd_);
}

UdpSender::UdpSender(UdpSender&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)), address_(other.address_), addressLength_(other.addressLength_),
      lastError_(std::move(other.lastError_)) {}

bool UdpSender::send(std::span<const std::uint8_t> datagram) {
    const ssize_t n = sendto(fd_, datagram.data(), datagram.size(), MSG_DONTWAIT | MSG_NOSIGNAL,
                             reinterpret_cast<const sockaddr*>(&address_), addressLength_);
    if (n == static_cast<ssize_t>(datagram.size())) return true;
    lastError_ = n < 0 ? std::strerror(errno) : "a datagram went out cut short";
    return false;
}

}  // namespace arcomp
