#include "video/streams/StreamSpec.hpp"

#include <arpa/inet.h>
#include <netdb.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <charconv>
#include <stdexcept>

namespace arcomp {

namespace {

int parsePort(const std::string& text, const std::string& url) {
    int port = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), port);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size() || port < 1 || port > 65535)
        throw std::invalid_argument(url + ": expected a port from 1 to 65535 after the host, got '" + text + "'");
    return port;
}

}  // namespace

bool isLoopbackHost(const std::string& host) {
    if (host == "localhost") return true;
    in_addr v4{};
    if (inet_pton(AF_INET, host.c_str(), &v4) == 1) return (ntohl(v4.s_addr) >> 24) == 127;
    return host == "::1";
}

std::string listenProblem(const StreamSpec& spec) {
    const bool srt = spec.protocol == StreamProtocol::Srt;
    if (srt && !spec.listener) return "";
    addrinfo hints{};
    hints.ai_family = AF_INET;
    hints.ai_socktype = srt ? SOCK_DGRAM : SOCK_STREAM;
    addrinfo* found = nullptr;
    if (getaddrinfo(spec.host.c_str(), std::to_string(spec.port).c_str(), &hints, &found) != 0 || found == nullptr)
        return spec.host + " is not an address of this machine";
    const int fd = socket(found->ai_family, found->ai_socktype, 0);
    std::string problem;
    if (fd < 0) {
        problem = std::string("cannot open a socket: ") + std::strerror(errno);
    } else {
        if (bind(fd, found->ai_addr, found->ai_addrlen) != 0)
            problem = errno == EADDRINUSE ? "port " + std::to_string(spec.port) + " on " + spec.host +
                                                " is taken (another station or program listens there)"
                                          : "cannot listen on " + spec.host + ":" + std::to_string(spec.port) + ": " +
                                                std::strerror(errno);
        close(fd);
    }
    freeaddrinfo(found);
    return problem;
}

std::string StreamSpec::describe() const {
    const std::string where = host + ":" + std::to_string(port);
    if (protocol == StreamProtocol::Rtsp) return "rtsp://" + where + path;
    return std::string("srt ") + (listener ? "listener on " : "caller to ") + where;
}

StreamSpec parseStreamUrl(const std::string& url) {
    StreamSpec s;
    std::string rest;
    if (url.rfind("srt://", 0) == 0) {
        rest = url.substr(6);
    } else if (url.rfind("rtsp://", 0) == 0) {
        s.protocol = StreamProtocol::Rtsp;
        rest = url.substr(7);
    } else {
        throw std::invalid_argument(url + ": expected srt://host:port or rtsp://host:port/name");
    }
    std::string query;
    if (const auto q = rest.find('?'); q != std::string::npos) {
        query = rest.substr(q + 1);
        rest.erase(q);
    }
    if (const auto slash = rest.find('/'); slash != std::string::npos) {
        s.path = rest.substr(slash);
        rest.erase(slash);
    }
    const auto colon = rest.rfind(':');
    if (colon == std::string::npos) throw std::invalid_argument(url + ": expected a port, as in host:9000 or :9000");
    s.host = rest.substr(0, colon);
    s.port = parsePort(rest.substr(colon + 1), url);
    if (s.host.find_first_of(" []@") != std::string::npos)
        throw std::invalid_argument(url + ": expected a host name or an IPv4 address before the port");

    if (s.protocol == StreamProtocol::Rtsp) {
        if (!query.empty()) throw std::invalid_argument(url + ": an RTSP URL takes no ?options");
        if (s.path.size() < 2 || s.path.find_first_of(" ?#") != std::string::npos || s.path.back() == '/')
            throw std::invalid_argument(url + ": expected a name after the port, as in rtsp://:8554/lobby");
        if (s.host.empty()) s.host = "127.0.0.1";
        return s;
    }
    if (!s.path.empty()) throw std::invalid_argument(url + ": an SRT URL has no path; expected srt://host:port");
    if (query == "mode=listener")
        s.listener = true;
    else if (!query.empty() && query != "mode=caller")
        throw std::invalid_argument(url + ": expected ?mode=listener or ?mode=caller, got ?" + query);
    if (s.host.empty()) {
        if (!s.listener)
            throw std::invalid_argument(url + ": a caller needs the host to send to, as in srt://192.168.1.20:9000");
        s.host = "127.0.0.1";
    }
    return s;
}

}  // namespace arcomp
