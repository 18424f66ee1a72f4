#pragma once
// A UDP socket bound to 127.0.0.1 on a free port: the far end of the
// station's show-control datagrams, for the benches and the tests.
//
//   LoopbackUdp sink;                                    // send to 127.0.0.1:sink.port()
//   std::vector<std::uint8_t> buffer(65536);
//   while (const std::size_t n = sink.receive(buffer, std::chrono::milliseconds(0))) use(buffer.data(), n);

#include <chrono>
#include <cstdint>
#include <span>

namespace arcomp {

class LoopbackUdp {
public:
    LoopbackUdp();  // throws std::runtime_error when there is no socket to bind
    ~LoopbackUdp();
    LoopbackUdp(const LoopbackUdp&) = delete;
    LoopbackUdp& operator=(const LoopbackUdp&) = delete;

    int port() const { return port_; }
    // One datagram into `buffer`, waiting up to `wait` for it; its size, or 0 when none came.
    std::size_t receive(std::span<std::uint8_t> buffer, std::chrono::milliseconds wait);

private:
    int fd_ = -1;
    int port_ = 0;
};

}  // namespace arcomp
