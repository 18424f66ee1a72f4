#include "graph/io/BinaryWriter.hpp"

#include <algorithm>
#include <bit>

namespace arcomp {

void BinaryWriter::raw(std::span<const char> bytes) {
    for (char c : bytes) bytes_.push_back(static_cast<std::byte>(c));
}

void BinaryWriter::littleEndian(std::uint64_t v, int byteCount) {
    for (int i = 0; i < byteCount; ++i) bytes_.push_back(static_cast<std::byte>((v >> (8 * i)) & 0xff));
}

void BinaryWriter::makeRoom(std::size_t byteCount) {
    // Grown geometrically still: reserving exactly, call after call, would
    // copy the whole buffer for every small array (a region's few vertices).
    const std::size_t needed = bytes_.size() + byteCount;
    if (needed > bytes_.capacity()) bytes_.reserve(std::max(needed, 2 * bytes_.capacity()));
}

void BinaryWriter::f32(float v) { u32(std::bit_cast<std::uint32_t>(v)); }

void BinaryWriter::u32s(std::span<const std::uint32_t> values) {
    makeRoom(4 * values.size());
    for (std::uint32_t v : values) u32(v);
}

void BinaryWriter::vec3s(std::span<const glm::vec3> values) {
    makeRoom(12 * values.size());
    for (const glm::vec3& v : values) {
        f32(v.x);
        f32(v.y);
        f32(v.z);
    }
}

void BinaryWriter::vec2s(std::span<const glm::vec2> values) {
    makeRoom(8 * values.size());
    for (const glm::vec2& v : values) {
        f32(v.x);
        f32(v.y);
    }
}

void BinaryWriter::vec4s(std::span<const glm::vec4> values) {
    makeRoom(16 * values.size());
    for (const glm::vec4& v : values) {
        f32(v.x);
        f32(v.y);
        f32(v.z);
        f32(v.w);
    }
}

}  // namespace arcomp
