#include "runtime/showcontrol/OscCueListener.hpp"

#include "runtime/showcontrol/CueDecode.hpp"
#include "runtime/showcontrol/UdpSender.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace arcomp {

OscCueListener::OscCueListener(const CueInputConfig& cfg) : buffer_(65536) {
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(cfg.listen.port));
    if (inet_pton(AF_INET, cfg.listen.host.c_str(), &address.sin_addr) != 1)
        throw ShowControlError(cfg.listen.where + ": '" + cfg.listen.host + "' is not an IPv4 address to listen on");
    for (const std::string& a : cfg.allow) {
        in_addr sender{};
        if (inet_pton(AF_INET, a.c_str(), &sender) == 1) allow_.push_back(sender.s_addr);
    }
    fd_ = socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    if (fd_ < 0) throw ShowControlError(cfg.listen.where + ": no UDP socket (" + std::strerror(errno) + ")");
    if (bind(fd_, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
        const std::string why = std::strerror(errno);
        close(fd_);
        throw ShowControlError(cfg.listen.where + ": cannot listen on " + cfg.listen.text() + " (" + why + ")");
    }
    socklen_t length = sizeof address;
    getsockname(fd_, reinterpret_cast<sockaddr*>(&address), &length);
    port_ = ntohs(address.sin_port);
}

OscCueListener::~OscCueListener() {
    if (fd_ >= 0) close(fd_);
}

void OscCueListener::poll(std::vector<ReceivedCue>& out, std::size_t most) {
    for (std::size_t i = 0; i < most; ++i) {
        sockaddr_in from{};
        socklen_t length = sizeof from;
        const ssize_t n =
            recvfrom(fd_, buffer_.data(), buffer_.size(), MSG_DONTWAIT, reinterpret_cast<sockaddr*>(&from), &length);
        if (n < 0) return;  // nothing more now (EAGAIN), or an error the next poll meets again
        ++counts_.received;
        char host[INET_ADDRSTRLEN] = "?";
        inet_ntop(AF_INET, &from.sin_addr, host, sizeof host);
        ReceivedCue r{.sender = std::string(host) + ":" + std::to_string(ntohs(from.sin_port)), .cue = std::nullopt};
        if (!allow_.empty() && std::find(allow_.begin(), allow_.end(), from.sin_addr.s_addr) == allow_.end()) {
            ++counts_.refusedSender;
            r.error = std::string("sender ") + host + " is not in show_control.cues.osc.allow; dropped";
        } else {
            CueDecoded d = decodeOscCue({buffer_.data(), static_cast<std::size_t>(n)});
            if (!d.cue) ++counts_.malformed;
            r.cue = std::move(d.cue);
            r.error = std::move(d.error);
        }
        out.push_back(std::move(r));
    }
}

}  // namespace arcomp
