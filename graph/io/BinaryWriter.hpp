#pragma once
// Building one of the project's little-endian binary files (.lod, .sil,
// .arvox) in memory, value by value, the mirror of BinaryReader. The bytes
// go to disk in one step through writeFileAtomically (AtomicFile.hpp).
//
//   constexpr char kMagic[8] = {'A', 'R', 'C', 'S', 'I', 'L', '\0', '\0'};
//   BinaryWriter out;
//   out.raw(kMagic);
//   out.u32(static_cast<std::uint32_t>(positions.size()));
//   out.vec3s(positions);
//   writeFileAtomically("bunny.sil", out.bytes());
//
// Little-endian whatever the host, floats by their bits (NaN payloads kept).

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace arcomp {

class BinaryWriter {
public:
    void reserve(std::size_t byteCount) { bytes_.reserve(byteCount); }

    void raw(std::span<const char> bytes);  // a magic, as it is
    void u8(std::uint8_t v) { bytes_.push_back(static_cast<std::byte>(v)); }
    void u16(std::uint16_t v) { littleEndian(v, 2); }
    void u32(std::uint32_t v) { littleEndian(v, 4); }
    void u64(std::uint64_t v) { littleEndian(v, 8); }
    void f32(float v);

    void u32s(std::span<const std::uint32_t> values);
    void vec3s(std::span<const glm::vec3> values);
    void vec2s(std::span<const glm::vec2> values);
    void vec4s(std::span<const glm::vec4> values);

    const std::vector<std::byte>& bytes() const { return bytes_; }
    std::vector<std::byte> take() { return std::move(bytes_); }

private:
    void littleEndian(std::uint64_t v, int byteCount);
    void makeRoom(std::size_t byteCount);

    std::vector<std::byte> bytes_;
};

}  // namespace arcomp
