#include "graph/io/BinaryReader.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace arcomp {

BinaryReader::BinaryReader(std::span<const std::byte> bytes, std::string name)
    : bytes_(bytes), name_(std::move(name)) {}

BinaryReader::BinaryReader(std::span<const unsigned char> bytes, std::string name)
    : BinaryReader(std::as_bytes(bytes), std::move(name)) {}

void BinaryReader::fail(const std::string& reason) const { failAt(position_, reason); }

void BinaryReader::failAt(std::size_t offset, const std::string& reason) const {
    throw ModelError(name_, "byte " + std::to_string(offset), reason);
}

void BinaryReader::need(std::uint64_t byteCount, const char* what) const {
    if (byteCount > remaining()) fail(std::string("file ends inside ") + what);
}

void BinaryReader::needItems(std::uint64_t count, std::size_t itemSize, const char* what) const {
    // Divided rather than multiplied: count * itemSize can wrap to a small number.
    if (count > remaining() / itemSize)
        fail(std::string("file ends inside ") + what + ": " + std::to_string(count) + " items of " +
             std::to_string(itemSize) + " bytes, " + std::to_string(remaining()) + " bytes left");
}

void BinaryReader::magic(std::span<const char> expected, const char* what, const std::string& wrongMagic) {
    need(expected.size(), what);
    const bool same =
        std::equal(expected.begin(), expected.end(), bytes_.begin() + static_cast<std::ptrdiff_t>(position_),
                   [](char e, std::byte b) { return static_cast<std::byte>(e) == b; });
    if (!same) fail(wrongMagic);
    position_ += expected.size();
}

std::uint64_t BinaryReader::littleEndian(int byteCount, const char* what) {
    need(static_cast<std::uint64_t>(byteCount), what);
    std::uint64_t v = 0;
    for (int i = 0; i < byteCount; ++i)
        v |= std::uint64_t{std::to_integer<std::uint8_t>(bytes_[position_ + static_cast<std::size_t>(i)])} << (8 * i);
    position_ += static_cast<std::size_t>(byteCount);
    return v;
}

std::uint8_t BinaryReader::u8(const char* what) { return static_cast<std::uint8_t>(littleEndian(1, what)); }
std::uint16_t BinaryReader::u16(const char* what) { return static_cast<std::uint16_t>(littleEndian(2, what)); }
std::uint32_t BinaryReader::u32(const char* what) { return static_cast<std::uint32_t>(littleEndian(4, what)); }
std::uint64_t BinaryReader::u64(const char* what) { return littleEndian(8, what); }

float BinaryReader::f32(const char* what) { return std::bit_cast<float>(u32(what)); }

float BinaryReader::finite(const char* what) {
    const float v = f32(what);
    if (!std::isfinite(v)) failAt(position_ - 4, std::string(what) + " is not a finite number");
    return v;
}

std::vector<glm::vec3> BinaryReader::vec3s(std::uint64_t count, const char* what) {
    needItems(count, 3 * sizeof(float), what);  // the size on disk, whatever glm pads to
    std::vector<glm::vec3> out;
    out.reserve(static_cast<std::size_t>(count));
    for (std::uint64_t i = 0; i < count; ++i) {
        const float x = finite(what), y = finite(what), z = finite(what);
        out.emplace_back(x, y, z);
    }
    return out;
}

std::vector<glm::vec2> BinaryReader::vec2s(std::uint64_t count, const char* what) {
    needItems(count, 2 * sizeof(float), what);
    std::vector<glm::vec2> out;
    out.reserve(static_cast<std::size_t>(count));
    for (std::uint64_t i = 0; i < count; ++i) {
        const float x = finite(what), y = finite(what);
        out.emplace_back(x, y);
    }
    return out;
}

std::vector<glm::vec4> BinaryReader::vec4s(std::uint64_t count, const char* what) {
    needItems(count, 4 * sizeof(float), what);
    std::vector<glm::vec4> out;
    out.reserve(static_cast<std::size_t>(count));
    for (std::uint64_t i = 0; i < count; ++i) {
        const float x = finite(what), y = finite(what), z = finite(what), w = finite(what);
        out.emplace_back(x, y, z, w);
    }
    return out;
}

}  // namespace arcomp
