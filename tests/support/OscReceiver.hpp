#pragma once
// A real OSC receiver for the tests, on loopback only: a UDP socket bound
// to 127.0.0.1 on a free port (tools/bench/probes/LoopbackUdp.hpp), and
// liblo's own parser and dispatcher (a
// liblo server on a local socket file, fed each datagram) turning the
// datagrams into messages, bundles unpacked in order.
//
//   OscReceiver rx(dir.path());
//   send to "127.0.0.1:" + std::to_string(rx.port());
//   const std::vector<OscReceiver::Message> got = rx.receive(std::chrono::seconds(2), 3);   // until 3 datagrams

#include "tools/bench/probes/LoopbackUdp.hpp"

#include <lo/lo.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace arcomp::test {

class OscReceiver {
public:
    using Argument = std::variant<std::int32_t, float, std::string>;
    struct Message {
        std::size_t datagram = 0;  // which datagram (bundle) it came in, from 0
        std::string path, types;
        std::vector<Argument> args;
        std::int32_t i(std::size_t k) const { return std::get<std::int32_t>(args.at(k)); }
        float f(std::size_t k) const { return std::get<float>(args.at(k)); }
        const std::string& s(std::size_t k) const { return std::get<std::string>(args.at(k)); }
    };

    explicit OscReceiver(const std::filesystem::path& folder) {
        const std::string unixPath = (folder / "osc-receiver.sock").string();
        server_ = lo_server_new_with_proto(unixPath.c_str(), LO_UNIX, nullptr);
        if (!server_) throw std::runtime_error("OscReceiver: liblo server on " + unixPath);
        lo_server_add_method(server_, nullptr, nullptr, &OscReceiver::onMessage, this);
    }
    ~OscReceiver() { lo_server_free(server_); }
    OscReceiver(const OscReceiver&) = delete;
    OscReceiver& operator=(const OscReceiver&) = delete;

    int port() const { return socket_.port(); }

    // Every message of the datagrams that arrive until `datagrams` of them
    // have (counting those before) or `wait` passes without one.
    std::vector<Message> receive(std::chrono::milliseconds wait, std::size_t datagrams) {
        std::vector<std::uint8_t> buffer(65536);
        while (datagramCount_ < datagrams) {
            const std::size_t n = socket_.receive(buffer, wait);
            if (n == 0) break;
            lo_server_dispatch_data(server_, buffer.data(), n);
            ++datagramCount_;
        }
        return messages_;
    }
    std::size_t datagrams() const { return datagramCount_; }

private:
    static int onMessage(const char* path, const char* types, lo_arg** argv, int argc, lo_message, void* self) {
        auto* r = static_cast<OscReceiver*>(self);
        Message m{.datagram = r->datagramCount_, .path = path, .types = types, .args = {}};
        // liblo's arguments point into the datagram, 4-byte aligned: copied out, not read through its 8-byte union.
        for (int k = 0; k < argc; ++k) {
            const auto* bytes = reinterpret_cast<const char*>(argv[k]);
            if (types[k] == 'i') {
                std::int32_t v = 0;
                std::memcpy(&v, bytes, sizeof v);
                m.args.emplace_back(v);
            } else if (types[k] == 'f') {
                float v = 0;
                std::memcpy(&v, bytes, sizeof v);
                m.args.emplace_back(v);
            } else if (types[k] == 's') {
                m.args.emplace_back(std::string(bytes));
            } else {
                m.args.emplace_back(std::string("?") + types[k]);
            }
        }
        r->messages_.push_back(std::move(m));
        return 0;
    }

    LoopbackUdp socket_;
    lo_server server_ = nullptr;
    std::size_t datagramCount_ = 0;
    std::vector<Message> messages_;
};

}  // namespace arcomp::test
