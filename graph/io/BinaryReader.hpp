#pragma once
// Reading the project's little-endian binary files (.lod, .sil, .arvox)
// from bytes in memory, trusting nothing in them. Every read is bounds
// checked, and every failure throws ModelError with where = "byte N".
//
//   constexpr char kMagic[8] = {'A', 'R', 'C', 'S', 'I', 'L', '\0', '\0'};
//   BinaryReader in(bytes, "bunny.sil");
//   in.magic(kMagic, "the header", "not a baked silhouette file (bad magic)");
//   const std::uint32_t count = in.u32("vertex count");
//   std::vector<glm::vec3> positions = in.vec3s(count, "vertex position");  // checked before allocating
//   if (in.remaining() != 0) in.fail("bytes after the last vertex");
//
// A count read from the file is checked against the bytes left before any
// memory is reserved for it: fuzzed files with a count of 2^32 must cost
// an error, not gigabytes.

#include "graph/io/ModelError.hpp"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace arcomp {

class BinaryReader {
public:
    // `name` stands for the file in errors. The bytes must outlive the reader.
    BinaryReader(std::span<const std::byte> bytes, std::string name);
    BinaryReader(std::span<const unsigned char> bytes, std::string name);

    std::size_t position() const { return position_; }
    std::size_t remaining() const { return bytes_.size() - position_; }
    std::size_t size() const { return bytes_.size(); }
    const std::string& name() const { return name_; }

    // Errors at the current position, or at an earlier one (the start of a
    // value found wrong only after it was read).
    [[noreturn]] void fail(const std::string& reason) const;
    [[noreturn]] void failAt(std::size_t offset, const std::string& reason) const;

    // "file ends inside <what>" unless `byteCount` more bytes are there.
    void need(std::uint64_t byteCount, const char* what) const;
    // The same for `count` items of `itemSize` bytes each, without the
    // multiplication that a hostile count could overflow.
    void needItems(std::uint64_t count, std::size_t itemSize, const char* what) const;

    // Consumes expected.size() bytes that must equal `expected`; otherwise
    // throws `wrongMagic` at the magic's start. A file too short for it ends
    // inside `what`. A span, not a string: magics hold '\0'.
    void magic(std::span<const char> expected, const char* what, const std::string& wrongMagic);

    std::uint8_t u8(const char* what);
    std::uint16_t u16(const char* what);
    std::uint32_t u32(const char* what);
    std::uint64_t u64(const char* what);
    float f32(const char* what);     // any bit pattern, NaN included
    float finite(const char* what);  // "<what> is not a finite number" at its first byte otherwise

    // `count` finite vectors; the count is checked against the bytes left first.
    std::vector<glm::vec3> vec3s(std::uint64_t count, const char* what);
    std::vector<glm::vec2> vec2s(std::uint64_t count, const char* what);
    std::vector<glm::vec4> vec4s(std::uint64_t count, const char* what);

private:
    std::uint64_t littleEndian(int byteCount, const char* what);

    std::span<const std::byte> bytes_;
    std::string name_;
    std::size_t position_ = 0;
};

}  // namespace arcomp
