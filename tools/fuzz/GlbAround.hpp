#pragma once
// A GLB file around a fuzzer's bytes: a fixed JSON chunk and the bytes as
// the BIN chunk (buffer 0), so that a target mutates one compressed stream
// while the document around it stays valid.
//
//   const std::string glb = glbAround(R"({"asset": {"version": "2.0"}, ...})", data, size);

#include <cstddef>
#include <cstdint>
#include <string>

namespace arcomp::fuzz {

inline std::string glbAround(std::string json, const std::uint8_t* bin, std::size_t size) {
    while (json.size() % 4) json += ' ';
    const std::size_t padded = (size + 3) / 4 * 4;
    std::string glb = "glTF";
    const auto u32 = [&glb](std::size_t v) {
        for (int k = 0; k < 4; ++k) glb += static_cast<char>((v >> (8 * k)) & 0xFF);
    };
    u32(2);
    u32(12 + 8 + json.size() + 8 + padded);
    u32(json.size());
    glb += "JSON" + json;
    u32(padded);
    glb += std::string("BIN\0", 4);
    glb.append(reinterpret_cast<const char*>(bin), size);
    glb.append(padded - size, '\0');
    return glb;
}

}  // namespace arcomp::fuzz
