#include "graph/io/VoxelFile.hpp"

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace arcomp {

namespace {

constexpr char kMagic[8] = {'A', 'R', 'C', 'V', 'O', 'X', 'E', 'L'};
constexpr std::size_t kHeaderSize = 40;
constexpr std::size_t kRecordSize = 10;

void putU16(std::vector<std::uint8_t>& out, std::uint16_t v) {
    out.push_back(static_cast<std::uint8_t>(v));
    out.push_back(static_cast<std::uint8_t>(v >> 8));
}
void putU32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}
void putU64(std::vector<std::uint8_t>& out, std::uint64_t v) {
    for (int i = 0; i < 8; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}
void putF32(std::vector<std::uint8_t>& out, float v) { putU32(out, std::bit_cast<std::uint32_t>(v)); }

std::uint64_t getLe(std::span<const std::uint8_t> b, std::size_t at, int bytes) {
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v |= std::uint64_t{b[at + static_cast<std::size_t>(i)]} << (8 * i);
    return v;
}
float getF32(std::span<const std::uint8_t> b, std::size_t at) {
    return std::bit_cast<float>(static_cast<std::uint32_t>(getLe(b, at, 4)));
}

} // namespace

std::vector<std::uint8_t> encodeVoxels(const VoxelGrid& grid) {
    std::vector<std::uint8_t> out(kMagic, kMagic + 8);
    out.reserve(kHeaderSize + grid.size() * kRecordSize);
    putU32(out, kVoxelFileVersion);
    putU32(out, static_cast<std::uint32_t>(grid.resolution));
    for (int i = 0; i < 3; ++i) putF32(out, grid.origin[i]);
    putF32(out, grid.voxelSize);
    putU64(out, grid.size());
    for (std::size_t i = 0; i < grid.size(); ++i) {
        for (int a = 0; a < 3; ++a) putU16(out, grid.cells[i][a]);
        for (int a = 0; a < 4; ++a) out.push_back(grid.colors[i][a]);
    }
    return out;
}

VoxelGrid decodeVoxels(std::span<const std::uint8_t> bytes, const std::string& name) {
    auto fail = [&](std::size_t offset, const std::string& reason) -> ModelError {
        return ModelError(name, "byte " + std::to_string(offset), reason);
    };
    if (bytes.size() < kHeaderSize)
        throw fail(0, "file is " + std::to_string(bytes.size()) + " bytes; a voxel file needs a 40-byte header");
    if (std::memcmp(bytes.data(), kMagic, 8) != 0) throw fail(0, "expected magic ARCVOXEL");
    const auto version = static_cast<std::uint32_t>(getLe(bytes, 8, 4));
    if (version != kVoxelFileVersion)
        throw fail(8, "version " + std::to_string(version) + " is not supported; expected 1");
    const auto resolution = getLe(bytes, 12, 4);
    if (resolution < 1 || resolution > kVoxelFileMaxResolution)
        throw fail(12, "resolution " + std::to_string(resolution) + " outside [1, 4096]");
    VoxelGrid grid;
    grid.resolution = static_cast<int>(resolution);
    for (int i = 0; i < 3; ++i) grid.origin[i] = getF32(bytes, 16 + 4 * static_cast<std::size_t>(i));
    grid.voxelSize = getF32(bytes, 28);
    if (!std::isfinite(grid.origin.x) || !std::isfinite(grid.origin.y) || !std::isfinite(grid.origin.z))
        throw fail(16, "origin is not finite");
    if (!std::isfinite(grid.voxelSize) || !(grid.voxelSize > 0.0f)) throw fail(28, "voxel size must be finite and > 0");
    const glm::vec3 far = grid.origin + grid.voxelSize * static_cast<float>(resolution);
    if (!std::isfinite(far.x) || !std::isfinite(far.y) || !std::isfinite(far.z))
        throw fail(28, "grid extent overflows");
    const std::uint64_t count = getLe(bytes, 32, 8);
    const std::uint64_t available = (bytes.size() - kHeaderSize) / kRecordSize;
    if (count > resolution * resolution * resolution)
        throw fail(32, "voxel count " + std::to_string(count) + " exceeds N^3");
    if (count > available || (bytes.size() - kHeaderSize) % kRecordSize != 0 || count != available)
        throw fail(32, "voxel count " + std::to_string(count) + " does not match the " +
                           std::to_string(bytes.size() - kHeaderSize) + " bytes of voxel records");
    grid.cells.reserve(count);
    grid.colors.reserve(count);
    std::uint64_t previous = 0;
    for (std::uint64_t i = 0; i < count; ++i) {
        const std::size_t at = kHeaderSize + i * kRecordSize;
        glm::u16vec3 cell;
        for (int a = 0; a < 3; ++a) {
            cell[a] = static_cast<std::uint16_t>(getLe(bytes, at + 2 * static_cast<std::size_t>(a), 2));
            if (cell[a] >= resolution) throw fail(at, "voxel " + std::to_string(i) + " lies outside the grid");
        }
        const std::uint64_t linear = cell.x + resolution * (cell.y + resolution * cell.z);
        if (i > 0 && linear <= previous)
            throw fail(at, "voxel " + std::to_string(i) + " is out of order or repeated");
        previous = linear;
        grid.cells.push_back(cell);
        grid.colors.emplace_back(bytes[at + 6], bytes[at + 7], bytes[at + 8], bytes[at + 9]);
    }
    return grid;
}

void writeVoxelFile(const std::filesystem::path& file, const VoxelGrid& grid) {
    const std::vector<std::uint8_t> bytes = encodeVoxels(grid);
    std::filesystem::path temporary = file;
    temporary += ".part";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
        if (!out) throw std::runtime_error(temporary.string() + ": cannot write");
    }
    std::error_code ec;
    std::filesystem::rename(temporary, file, ec);
    if (ec) throw std::runtime_error(file.string() + ": cannot rename from " + temporary.string() + ": " + ec.message());
}

VoxelGrid readVoxelFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw ModelError(file.string(), "", "cannot open");
    std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw ModelError(file.string(), "", "read failed");
    return decodeVoxels(bytes, file.string());
}

} // namespace arcomp
