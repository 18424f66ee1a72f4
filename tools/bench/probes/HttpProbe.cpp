#include "tools/bench/probes/HttpProbe.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace arcomp {

FileDescriptor connectLoopback(int port, const std::string& from) {
    FileDescriptor socket(::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0));
    if (!socket) throw std::runtime_error(std::string("socket: ") + std::strerror(errno));
    sockaddr_in source{};
    source.sin_family = AF_INET;
    if (inet_pton(AF_INET, from.c_str(), &source.sin_addr) != 1 ||
        ::bind(socket.get(), reinterpret_cast<const sockaddr*>(&source), sizeof source) != 0)
        throw std::runtime_error("cannot bind a client socket to " + from + ": " + std::strerror(errno));
    sockaddr_in target{};
    target.sin_family = AF_INET;
    target.sin_port = htons(static_cast<std::uint16_t>(port));
    target.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(socket.get(), reinterpret_cast<const sockaddr*>(&target), sizeof target) != 0 && errno != EINPROGRESS)
        throw std::runtime_error("cannot connect to 127.0.0.1:" + std::to_string(port) + ": " + std::strerror(errno));
    return socket;
}

HttpProbeReply httpGet(int port, const std::string& path, const HttpProbeRequest& request) {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point deadline = Clock::now() + request.timeout;
    HttpProbeReply reply;
    FileDescriptor socket;
    try {
        socket = connectLoopback(port, request.from);
    } catch (const std::exception& e) {
        reply.error = e.what();
        return reply;
    }
    const std::string out = "GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1\r\n" + request.extraHeaders + "\r\n";
    std::size_t sent = 0;
    std::string in;
    char buffer[16384];
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
        if (left <= 0) {
            reply.error = "no whole reply within " + std::to_string(request.timeout.count()) + " ms";
            return reply;
        }
        pollfd p{socket.get(), static_cast<short>(sent < out.size() ? POLLOUT : POLLIN), 0};
        if (::poll(&p, 1, static_cast<int>(left)) <= 0) continue;
        if (sent < out.size()) {
            const ssize_t n = ::send(socket.get(), out.data() + sent, out.size() - sent, MSG_NOSIGNAL);
            if (n < 0 && errno != EAGAIN && errno != EINTR) {
                reply.error = std::string("send: ") + std::strerror(errno);
                return reply;
            }
            if (n > 0) sent += static_cast<std::size_t>(n);
            continue;
        }
        const ssize_t n = ::recv(socket.get(), buffer, sizeof buffer, 0);
        if (n > 0) {
            in.append(buffer, static_cast<std::size_t>(n));
            continue;
        }
        if (n < 0 && (errno == EAGAIN || errno == EINTR)) continue;
        if (n < 0) {
            reply.error = std::string("recv: ") + std::strerror(errno);
            return reply;
        }
        break;  // the server closes after its reply
    }
    const std::size_t headEnd = in.find("\r\n\r\n");
    if (in.compare(0, 9, "HTTP/1.1 ") != 0 || headEnd == std::string::npos) {
        reply.error = "the connection closed without a whole reply (" + std::to_string(in.size()) + " bytes)";
        return reply;
    }
    reply.status = std::atoi(in.c_str() + 9);
    reply.head = in.substr(0, headEnd);
    reply.body = in.substr(headEnd + 4);
    return reply;
}

}  // namespace arcomp
