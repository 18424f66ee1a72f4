#include "graph/io/VoxelFile.hpp"

#include "graph/io/AtomicFile.hpp"
#include "graph/io/BinaryReader.hpp"
#include "graph/io/BinaryWriter.hpp"

#include <cmath>
#include <fstream>

namespace arcomp {

namespace {

// Names unique to this format, so that a unity build may join this file
// with the other formats' readers.
constexpr char kVoxelMagic[8] = {'A', 'R', 'C', 'V', 'O', 'X', 'E', 'L'};
constexpr std::size_t kVoxelHeaderSize = 40;
constexpr std::size_t kVoxelRecordSize = 10;

BinaryWriter voxelFileBytes(const VoxelGrid& grid) {
    BinaryWriter out;
    out.reserve(kVoxelHeaderSize + grid.size() * kVoxelRecordSize);
    out.raw(kVoxelMagic);
    out.u32(kVoxelFileVersion);
    out.u32(static_cast<std::uint32_t>(grid.resolution));
    for (int i = 0; i < 3; ++i) out.f32(grid.origin[i]);
    out.f32(grid.voxelSize);
    out.u64(grid.size());
    for (std::size_t i = 0; i < grid.size(); ++i) {
        for (int a = 0; a < 3; ++a) out.u16(grid.cells[i][a]);
        for (int a = 0; a < 4; ++a) out.u8(grid.colors[i][a]);
    }
    return out;
}

}  // namespace

std::vector<std::uint8_t> encodeVoxels(const VoxelGrid& grid) {
    const BinaryWriter out = voxelFileBytes(grid);
    const auto* first = reinterpret_cast<const std::uint8_t*>(out.bytes().data());
    return {first, first + out.bytes().size()};
}

// Errors name the offset where each field starts, as in the layout in VoxelFile.hpp.
VoxelGrid decodeVoxels(std::span<const std::uint8_t> bytes, const std::string& name) {
    BinaryReader r(bytes, name);
    if (r.remaining() < kVoxelHeaderSize)
        r.failAt(0, "file is " + std::to_string(r.size()) + " bytes; a voxel file needs a 40-byte header");
    r.magic(kVoxelMagic, "the header", "expected magic ARCVOXEL");
    const std::uint32_t version = r.u32("the header");
    if (version != kVoxelFileVersion)
        r.failAt(8, "version " + std::to_string(version) + " is not supported; expected 1");
    const std::uint64_t resolution = r.u32("the header");
    if (resolution < 1 || resolution > kVoxelFileMaxResolution)
        r.failAt(12, "resolution " + std::to_string(resolution) + " outside [1, 4096]");
    VoxelGrid grid;
    grid.resolution = static_cast<int>(resolution);
    for (int i = 0; i < 3; ++i) grid.origin[i] = r.f32("the header");
    grid.voxelSize = r.f32("the header");
    if (!std::isfinite(grid.origin.x) || !std::isfinite(grid.origin.y) || !std::isfinite(grid.origin.z))
        r.failAt(16, "origin is not finite");
    if (!std::isfinite(grid.voxelSize) || !(grid.voxelSize > 0.0f)) r.failAt(28, "voxel size must be finite and > 0");
    const glm::vec3 far = grid.origin + grid.voxelSize * static_cast<float>(resolution);
    if (!std::isfinite(far.x) || !std::isfinite(far.y) || !std::isfinite(far.z)) r.failAt(28, "grid extent overflows");
    const std::uint64_t count = r.u64("the header");
    // The records must fill the rest of the file exactly, checked before
    // anything is reserved for `count` of them.
    const std::uint64_t recordBytes = r.remaining();
    if (count > resolution * resolution * resolution)
        r.failAt(32, "voxel count " + std::to_string(count) + " exceeds N^3");
    if (recordBytes % kVoxelRecordSize != 0 || count != recordBytes / kVoxelRecordSize)
        r.failAt(32, "voxel count " + std::to_string(count) + " does not match the " + std::to_string(recordBytes) +
                         " bytes of voxel records");
    grid.cells.reserve(count);
    grid.colors.reserve(count);
    std::uint64_t previous = 0;
    for (std::uint64_t i = 0; i < count; ++i) {
        const std::size_t at = r.position();
        glm::u16vec3 cell;
        for (int a = 0; a < 3; ++a) {
            cell[a] = r.u16("a voxel record");
            if (cell[a] >= resolution) r.failAt(at, "voxel " + std::to_string(i) + " lies outside the grid");
        }
        const std::uint64_t linear = cell.x + resolution * (cell.y + resolution * cell.z);
        if (i > 0 && linear <= previous) r.failAt(at, "voxel " + std::to_string(i) + " is out of order or repeated");
        previous = linear;
        grid.cells.push_back(cell);
        glm::u8vec4 color;
        for (int c = 0; c < 4; ++c) color[c] = r.u8("a voxel record");
        grid.colors.push_back(color);
    }
    return grid;
}

void writeVoxelFile(const std::filesystem::path& file, const VoxelGrid& grid) {
    writeFileAtomically(file, voxelFileBytes(grid).bytes());
}

VoxelGrid readVoxelFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw ModelError(file.string(), "", "cannot open");
    std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw ModelError(file.string(), "", "read failed");
    return decodeVoxels(bytes, file.string());
}

}  // namespace arcomp
