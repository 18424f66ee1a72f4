#pragma once
// Cues over OSC (runtime/triggers/Cue.hpp): a UDP socket bound where the
// config says (loopback by default), read without waiting once a frame.
// Each datagram's sender is checked against the allow-list before a byte
// of it is decoded; what comes from elsewhere is dropped and counted, and
// so is what does not decode (runtime/showcontrol/CueDecode.hpp).
//
//   OscCueListener in(cfg.showControl.cues);      // throws ShowControlError: the port cannot be bound
//   std::vector<ReceivedCue> cues;
//   in.poll(cues);                                // each frame; never blocks
//   for (const ReceivedCue& c : cues) if (c.cue) station.cue(*c.cue);

#include "runtime/config/ShowControlConfig.hpp"
#include "runtime/triggers/Cue.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace arcomp {

struct ReceivedCue {
    std::string sender;  // "127.0.0.1:53211"
    std::optional<Cue> cue;
    std::string error{};  // no cue: why (a sender not allowed, a malformed packet)
};

struct CueInputCounts {
    std::uint64_t received = 0;  // datagrams read
    std::uint64_t refusedSender = 0;
    std::uint64_t malformed = 0;  // from an allowed sender, but no cue
};

class OscCueListener {
public:
    explicit OscCueListener(const CueInputConfig& cfg);
    ~OscCueListener();
    OscCueListener(const OscCueListener&) = delete;
    OscCueListener& operator=(const OscCueListener&) = delete;

    // Reads what has arrived, at most `most` datagrams, appending one entry
    // each to `out`; returns at once when nothing has.
    void poll(std::vector<ReceivedCue>& out, std::size_t most = 64);
    int port() const { return port_; }  // the one bound (the config's 0: any free one)
    const CueInputCounts& counts() const { return counts_; }

private:
    int fd_ = -1;
    int port_ = 0;
    std::vector<std::uint32_t> allow_;  // network order; empty: any (bound on loopback)
    std::vector<std::uint8_t> buffer_;
    CueInputCounts counts_;
};

}  // namespace arcomp
