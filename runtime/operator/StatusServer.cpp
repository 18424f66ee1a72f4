#include "runtime/operator/StatusServer.hpp"

#include "graph/core/BadInput.hpp"
#include "runtime/config/StatusAccess.hpp"
#include "runtime/operator/FileDescriptor.hpp"
#include "runtime/operator/HttpRequest.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <pthread.h>
#include <sys/eventfd.h>
#include <sys/socket.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

namespace arcomp {
namespace {

using Clock = std::chrono::steady_clock;

struct Connection {
    FileDescriptor socket;
    std::uint32_t client = 0;  // IPv4 address
    Clock::time_point lastHeard;
    Clock::time_point deadline;
    std::string received;
    std::string reply;  // empty while the request is still arriving
    std::size_t sent = 0;
    bool closed = false;  // removed at the end of the poll round

    bool replying() const { return !reply.empty(); }
};

std::string httpReply(int code, const char* reason, const char* contentType, const std::string& body,
                      const char* extraHeader = "") {
    return "HTTP/1.1 " + std::to_string(code) + " " + reason + "\r\nContent-Type: " + contentType +
           "\r\nContent-Length: " + std::to_string(body.size()) +
           "\r\nConnection: close\r\nCache-Control: no-store\r\n" + extraHeader + "\r\n" + body;
}

std::string errorReply(int code, const char* reason, const std::string& detail, const char* extraHeader = "") {
    return httpReply(code, reason, "text/plain; charset=utf-8", detail + "\n", extraHeader);
}

}  // namespace

struct StatusServer::Impl {
    Impl(const StationMetrics& m, StatusLimits l) : metrics(m), limits(l) {}

    const StationMetrics& metrics;
    const StatusLimits limits;
    std::string token;  // empty: no token asked (loopback without a token file)
    FileDescriptor listener;
    FileDescriptor wake;  // an eventfd written once to stop the thread
    std::vector<Connection> connections;
    Clock::time_point acceptPausedUntil{};
    std::thread thread;

    std::atomic<std::uint64_t> served{0}, refused{0}, unauthorized{0}, evicted{0}, timedOut{0};

    void run();
    void acceptWaiting(Clock::time_point now);
    void admit(FileDescriptor socket, std::uint32_t client, Clock::time_point now);
    bool evictIdlest(std::optional<std::uint32_t> client);
    void receive(Connection& c, Clock::time_point now);
    void send(Connection& c);
    std::string answer(const HttpRequestHead& head);
};

void StatusServer::Impl::run() {
    std::vector<pollfd> polled;
    for (;;) {
        const Clock::time_point before = Clock::now();
        const bool accepting = before >= acceptPausedUntil;
        Clock::time_point wakeAt = before + std::chrono::seconds(1);
        if (!accepting) wakeAt = std::min(wakeAt, acceptPausedUntil);
        polled.clear();
        polled.push_back({wake.get(), POLLIN, 0});
        polled.push_back({listener.get(), static_cast<short>(accepting ? POLLIN : 0), 0});
        for (const Connection& c : connections) {
            polled.push_back({c.socket.get(), static_cast<short>(c.replying() ? POLLOUT : POLLIN), 0});
            wakeAt = std::min(wakeAt, c.deadline);
        }
        const auto waitMs = std::chrono::ceil<std::chrono::milliseconds>(wakeAt - before).count();
        if (::poll(polled.data(), polled.size(), static_cast<int>(std::max<long long>(waitMs, 0))) < 0 &&
            errno != EINTR)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));  // ENOMEM: try again shortly
        if (polled[0].revents != 0) return;

        const Clock::time_point now = Clock::now();
        for (std::size_t i = 0; i < connections.size(); ++i) {
            if (polled[i + 2].revents == 0) continue;
            Connection& c = connections[i];
            if (c.replying())
                send(c);
            else
                receive(c, now);
        }
        for (Connection& c : connections)
            if (!c.closed && now >= c.deadline) {
                c.closed = true;
                ++timedOut;
            }
        if (polled[1].revents & POLLIN) acceptWaiting(now);
        std::erase_if(connections, [](const Connection& c) { return c.closed; });
    }
}

void StatusServer::Impl::acceptWaiting(Clock::time_point now) {
    // A batch of at most half the table, so that a flood of connects can
    // neither starve the connections already open nor evict, within one
    // round, a connection accepted in the same round: a scraper's request
    // is read (just below, or at the next round) before it can be closed.
    for (int i = 0; i < std::max(1, limits.maxConnections / 2); ++i) {
        sockaddr_in peer{};
        socklen_t length = sizeof peer;
        const int fd =
            ::accept4(listener.get(), reinterpret_cast<sockaddr*>(&peer), &length, SOCK_NONBLOCK | SOCK_CLOEXEC);
        if (fd >= 0) {
            admit(FileDescriptor(fd), ntohl(peer.sin_addr.s_addr), now);
            continue;
        }
        if (errno == EINTR || errno == ECONNABORTED) continue;
        if (errno == EMFILE || errno == ENFILE || errno == ENOBUFS || errno == ENOMEM) {
            // Out of descriptors: free the idlest (closed at the end of this
            // round), or stop accepting for a moment rather than spin on a
            // listener that stays readable.
            if (!evictIdlest(std::nullopt)) acceptPausedUntil = now + std::chrono::milliseconds(100);
        }
        return;  // EAGAIN: none waiting
    }
}

void StatusServer::Impl::admit(FileDescriptor socket, std::uint32_t client, Clock::time_point now) {
    int open = 0, fromClient = 0;
    for (const Connection& c : connections) {
        if (c.closed) continue;
        ++open;
        if (c.client == client) ++fromClient;
    }
    // A client over its share makes room among its own connections; only a
    // full table takes room from everyone's.
    const bool room = fromClient >= limits.maxPerClient ? evictIdlest(client)
                      : open >= limits.maxConnections   ? evictIdlest(std::nullopt)
                                                        : true;
    if (!room) {  // every candidate is mid-reply: the new connection goes instead
        ++evicted;
        return;
    }
    Connection& c = connections.emplace_back();
    c.socket = std::move(socket);
    c.client = client;
    c.lastHeard = now;
    c.deadline = now + limits.requestTimeout;
    // A scraper sends its request as soon as it is connected, so it is
    // often here already: answered now, it is never the idlest.
    receive(c, now);
}

bool StatusServer::Impl::evictIdlest(std::optional<std::uint32_t> client) {
    Connection* idlest = nullptr;
    for (Connection& c : connections) {
        if (c.closed || c.replying() || (client && c.client != *client)) continue;
        if (!idlest || c.lastHeard < idlest->lastHeard) idlest = &c;
    }
    if (!idlest) return false;
    idlest->closed = true;
    ++evicted;
    return true;
}

void StatusServer::Impl::receive(Connection& c, Clock::time_point now) {
    char buffer[4096];
    // An HTTP/1.0-style client (`nc -N`) shuts its side once the request is
    // out: what it sent before the end still deserves an answer.
    bool hungUp = false;
    while (c.received.size() <= kMaxHttpHeadBytes) {
        const ssize_t n = ::recv(c.socket.get(), buffer, sizeof buffer, 0);
        if (n > 0) {
            c.received.append(buffer, static_cast<std::size_t>(n));
            c.lastHeard = now;
            continue;
        }
        if (n < 0 && errno == EINTR) continue;
        if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;
        if (n == 0) {
            hungUp = true;
            break;
        }
        c.closed = true;  // reset
        return;
    }
    const HttpRequestHead head = parseHttpRequestHead(c.received);
    switch (head.state) {
    case HttpRequestHead::Incomplete:
        c.closed = hungUp;  // hung up before a whole request: no one to answer
        return;
    case HttpRequestHead::TooLarge:
        ++refused;
        c.reply = errorReply(431, "Request Header Fields Too Large",
                             "the request head is over " + std::to_string(kMaxHttpHeadBytes) + " bytes");
        break;
    case HttpRequestHead::Bad:
        ++refused;
        c.reply = errorReply(400, "Bad Request", head.error);
        break;
    case HttpRequestHead::Complete: c.reply = answer(head); break;
    }
    // As long again to take the reply; most replies go out at once below.
    c.deadline = now + limits.requestTimeout;
    send(c);
}

std::string StatusServer::Impl::answer(const HttpRequestHead& head) {
    // The token first: a client without it learns nothing, not even which paths exist.
    if (!token.empty() && !bearerTokenMatches(head.authorization, token)) {
        ++refused;
        ++unauthorized;
        return errorReply(401, "Unauthorized",
                          head.authorization.empty() ? "this endpoint needs `Authorization: Bearer <token>`"
                                                     : "wrong token",
                          "WWW-Authenticate: Bearer realm=\"arcomp\"\r\n");
    }
    if (head.method != "GET") {
        ++refused;
        return errorReply(405, "Method Not Allowed", "only GET is answered", "Allow: GET\r\n");
    }
    if (head.path == "/status") {
        ++served;
        return httpReply(200, "OK", "application/json", metrics.statusJson());
    }
    if (head.path == "/metrics") {
        ++served;
        return httpReply(200, "OK", "text/plain; version=0.0.4", metrics.prometheusText());
    }
    ++refused;
    return errorReply(404, "Not Found", "this endpoint answers GET /status and GET /metrics");
}

void StatusServer::Impl::send(Connection& c) {
    while (c.sent < c.reply.size()) {
        const ssize_t n = ::send(c.socket.get(), c.reply.data() + c.sent, c.reply.size() - c.sent, MSG_NOSIGNAL);
        if (n > 0) {
            c.sent += static_cast<std::size_t>(n);
            continue;
        }
        if (n < 0 && errno == EINTR) continue;
        if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return;  // the rest when the socket drains
        c.closed = true;
        return;
    }
    // Read what the client sent beyond its request head first: closing with
    // unread bytes makes the kernel reset the connection, and a reset can
    // discard the reply before the client has read it.
    char discard[4096];
    for (int i = 0; i < 16 && ::recv(c.socket.get(), discard, sizeof discard, 0) > 0; ++i) {}
    ::shutdown(c.socket.get(), SHUT_WR);
    c.closed = true;
}

StatusServer::StatusServer(const StationMetrics& metrics, const StatusEndpoint& endpoint)
    : impl_(std::make_unique<Impl>(metrics, endpoint.limits)) {
    const std::string address = endpoint.bind + ":" + std::to_string(endpoint.port);
    if (!endpoint.tokenFile.empty())
        impl_->token = readBearerToken(endpoint.tokenFile);
    else if (!isLoopbackAddress(endpoint.bind))
        throw BadInput("status", "bind " + endpoint.bind,
                       "an endpoint beyond loopback needs status.token_file (a file holding the bearer token)");

    sockaddr_in socketAddress{};
    socketAddress.sin_family = AF_INET;
    socketAddress.sin_port = htons(static_cast<std::uint16_t>(endpoint.port));
    if (inet_pton(AF_INET, endpoint.bind.c_str(), &socketAddress.sin_addr) != 1)
        throw BadInput("status", "bind " + endpoint.bind, "expected an IPv4 address such as 127.0.0.1");
    impl_->listener = FileDescriptor(::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0));
    // SO_REUSEADDR so that a restarted station binds again while old
    // connections linger; not SO_REUSEPORT, which would let a second
    // station share the port and answer half the scrapes.
    const int yes = 1;
    if (!impl_->listener || ::setsockopt(impl_->listener.get(), SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes) != 0 ||
        ::bind(impl_->listener.get(), reinterpret_cast<const sockaddr*>(&socketAddress), sizeof socketAddress) != 0 ||
        ::listen(impl_->listener.get(), SOMAXCONN) != 0)
        throw std::runtime_error("status server: cannot listen on " + address + ": " + std::strerror(errno) +
                                 " (address in use, or not an address of this machine)");
    socklen_t length = sizeof socketAddress;
    ::getsockname(impl_->listener.get(), reinterpret_cast<sockaddr*>(&socketAddress), &length);
    port_ = ntohs(socketAddress.sin_port);

    impl_->wake = FileDescriptor(::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK));
    if (!impl_->wake)
        throw std::runtime_error("status server: cannot create its eventfd: " + std::string(std::strerror(errno)));
    impl_->thread = std::thread([impl = impl_.get()] {
        pthread_setname_np(pthread_self(), "arcomp-status");
        impl->run();
    });
}

StatusServer::~StatusServer() {
    const std::uint64_t one = 1;
    [[maybe_unused]] const ssize_t written = ::write(impl_->wake.get(), &one, sizeof one);
    impl_->thread.join();
}

StatusServerCounters StatusServer::counters() const {
    return {impl_->served, impl_->refused, impl_->unauthorized, impl_->evicted, impl_->timedOut};
}

}  // namespace arcomp
