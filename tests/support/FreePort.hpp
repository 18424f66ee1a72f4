#pragma once
// A loopback port that no one uses at the moment of asking, for a test's
// own listener or receiver. (Another process may take it before the test
// binds it; on a test machine that is rare, and the test then fails loudly.)
//
//   const int port = test::freeLoopbackPort(SOCK_DGRAM);   // SRT is UDP

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace arcomp::test {

// `type`: SOCK_DGRAM for SRT, SOCK_STREAM for RTSP.
inline int freeLoopbackPort(int type) {
    const int fd = socket(AF_INET, type, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address);
    socklen_t length = sizeof address;
    getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length);
    close(fd);
    return ntohs(address.sin_port);
}

}  // namespace arcomp::test
