#pragma once
// Where one stream of the composite goes, as a config names it by URL:
//
//   srt://192.168.1.20:9000               SRT caller: arcomp sends to a listener (OBS, a recorder)
//   srt://:9000?mode=listener             SRT listener on loopback: receivers call arcomp
//   srt://0.0.0.0:9000?mode=listener      ... on every interface (needs a passphrase)
//   rtsp://:8554/lobby                    RTSP served by arcomp on loopback, path /lobby
//
//   StreamSpec s = parseStreamUrl("srt://:9000?mode=listener");  // throws std::invalid_argument with why

#include "video/streams/H264Settings.hpp"

#include <string>

namespace arcomp {

enum class StreamProtocol { Srt, Rtsp };

struct StreamSpec {
    std::string name;  // for logs, /status and /metrics
    StreamProtocol protocol = StreamProtocol::Srt;
    // A caller's destination; a listener's or an RTSP server's local
    // address, loopback (127.0.0.1) when the URL leaves it out.
    std::string host;
    int port = 0;
    bool listener = false;       // SRT: wait for receivers to call; RTSP always serves
    std::string path;            // RTSP: the mount, "/lobby"
    int latencyMs = 120;         // SRT's receive buffer: what a lost packet may take to be sent again
    std::string passphrase;      // SRT: AES with a key from this (10 to 79 characters); empty: none
    std::string user, password;  // RTSP: Basic authentication; empty: none
    H264Settings encoding{};
    int queueFrames = 4;  // frames waiting for the encoder before new ones are dropped

    // A human label: "srt caller to 192.168.1.20:9000".
    std::string describe() const;
};

// The protocol, host, port, mode and path of `url`; other fields keep
// their defaults. Throws std::invalid_argument saying what is wrong and
// what was expected.
StreamSpec parseStreamUrl(const std::string& url);

bool isLoopbackHost(const std::string& host);

// Why a stream that listens (an SRT listener, an RTSP server) could not
// bind its address and port now ("port 9000 on 127.0.0.1 is taken"); empty
// when it could, or when the stream calls out. For `arcomp check`: a
// running station holds its own ports.
std::string listenProblem(const StreamSpec& spec);

}  // namespace arcomp
