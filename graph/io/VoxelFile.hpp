#pragma once
// The voxel file (.arvox), version 1: what `arcomp bake voxels` writes and
// the point-cloud loader reads. Little-endian throughout:
//
//   offset  size  field
//   0       8     magic "ARCVOXEL"
//   8       4     u32 version (1)
//   12      4     u32 resolution N, 1..4096
//   16      12    f32 origin x, y, z (finite)
//   28      4     f32 voxel size (finite, > 0)
//   32      8     u64 voxel count, at most N^3
//   40      10*n  per voxel: u16 x, y, z (< N), u8 r, g, b, a (straight alpha)
//
// Voxels are sorted by x + N*(y + N*z), strictly (no cell twice), and the
// file ends right after the last one. The reader trusts nothing in the
// file: every size is checked against the bytes actually present before it
// is used, and any violation throws ModelError naming the byte offset.
//
//   writeVoxelFile("tree.arvox", grid);
//   VoxelGrid g = readVoxelFile("tree.arvox");

#include "graph/io/ModelError.hpp"
#include "graph/points/VoxelGrid.hpp"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace arcomp {

inline constexpr std::uint32_t kVoxelFileVersion = 1;
inline constexpr int kVoxelFileMaxResolution = 4096;

std::vector<std::uint8_t> encodeVoxels(const VoxelGrid& grid);
// `name` appears in error messages (a file path, or "<memory>").
VoxelGrid decodeVoxels(std::span<const std::uint8_t> bytes, const std::string& name = "<memory>");

// Writes to a temporary file beside `file` and renames it, so a crash never
// leaves a half-written model. Throws std::runtime_error on I/O failure.
void writeVoxelFile(const std::filesystem::path& file, const VoxelGrid& grid);
VoxelGrid readVoxelFile(const std::filesystem::path& file);

}  // namespace arcomp
