#pragma once
// Base64 (RFC 4648, with padding), for writing glTF data URIs: the feature
// models the glTF reference bench generates and the models tests write.
// Reading them is tinygltf's job.
//
//   std::string uri = "data:application/octet-stream;base64," + base64(bytes.data(), bytes.size());

#include <cstddef>
#include <cstdint>
#include <string>
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

}  // namespace arcomp
