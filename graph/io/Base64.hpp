#pragma once
// Base64 (RFC 4648, with padding), for glTF data URIs: written by the
// feature models the glTF reference bench generates and the models tests
// write, read by the glTF reader (graph/io/DataUri.hpp).
//
//   std::string uri = "data:application/octet-stream;base64," + base64(bytes.data(), bytes.size());
//   std::optional<std::vector<std::uint8_t>> back = fromBase64(uri.substr(uri.find(',') + 1));

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace arcomp {

inline std::string base64(const std::uint8_t* data, std::size_t size) {
    static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((size + 2) / 3 * 4);
    for (std::size_t i = 0; i < size; i += 3) {
        const std::uint32_t a = data[i], b = i + 1 < size ? data[i + 1] : 0, c = i + 2 < size ? data[i + 2] : 0;
        const std::uint32_t triple = a << 16 | b << 8 | c;
        out += kDigits[triple >> 18 & 63];
        out += kDigits[triple >> 12 & 63];
        out += i + 1 < size ? kDigits[triple >> 6 & 63] : '=';
        out += i + 2 < size ? kDigits[triple & 63] : '=';
    }
    return out;
}

inline std::string base64(const std::vector<std::uint8_t>& bytes) { return base64(bytes.data(), bytes.size()); }

// The bytes of base64 text, padded or not; nullopt at a character outside
// the alphabet or a length no encoder writes.
inline std::optional<std::vector<std::uint8_t>> fromBase64(std::string_view text) {
    while (!text.empty() && text.back() == '=') text.remove_suffix(1);
    if (text.size() % 4 == 1) return std::nullopt;
    std::vector<std::uint8_t> out;
    out.reserve(text.size() / 4 * 3 + 2);
    std::uint32_t bits = 0;
    int held = 0;
    for (const char c : text) {
        int v = -1;
        if (c >= 'A' && c <= 'Z')
            v = c - 'A';
        else if (c >= 'a' && c <= 'z')
            v = c - 'a' + 26;
        else if (c >= '0' && c <= '9')
            v = c - '0' + 52;
        else if (c == '+')
            v = 62;
        else if (c == '/')
            v = 63;
        if (v < 0) return std::nullopt;
        bits = bits << 6 | static_cast<std::uint32_t>(v);
        held += 6;
        if (held >= 8) {
            held -= 8;
            out.push_back(static_cast<std::uint8_t>(bits >> held & 0xFF));
        }
    }
    return out;
}

}  // namespace arcomp
