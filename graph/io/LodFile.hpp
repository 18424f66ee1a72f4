#pragma once
// The file `arcomp bake lod` writes: a mesh's LOD levels, finest first.
//
//   writeLodFile("bunny.lod", levels);                      // replaced in one step (AtomicFile.hpp)
//   std::vector<LodLevel> back = readLodFile("bunny.lod");   // throws ModelError
//
// Layout, little-endian, version 1:
//   "ARCOMPLD" (8 bytes), u32 version, u32 level count (1..8);
//   per level: f32 ratio, f32 error, u32 vertex count, u32 index count,
//   u32 flags (bit 0: normals, bit 1: texcoords, bit 2: texcoords1, bit 3:
//   tangents, bit 4: the tangents were generated), then positions (3 f32
//   each), normals (3 f32 each) if flagged, texcoords (2 f32 each) if
//   flagged, texcoords1 (2 f32 each) if flagged, tangents (4 f32 each, w the
//   bitangent's sign) if flagged, indices (u32, a multiple of 3, each below
//   the vertex count).
// Bits 2 to 4 came later without a new version: every file written before
// reads as it did, and a reader from before refuses the new bits as unknown
// flags, so the cache is made again rather than read without them.
// The reader checks every count against the bytes left before it allocates,
// and every value it reads; errors name the file and the byte or level.

#include "graph/io/ModelError.hpp"
#include "graph/lod/LodLevels.hpp"

#include <filesystem>
#include <vector>

namespace arcomp {

inline constexpr std::uint32_t kLodFileVersion = 1;

void writeLodFile(const std::filesystem::path& file, const std::vector<LodLevel>& levels);
std::vector<LodLevel> readLodFile(const std::filesystem::path& file);
// The same check on bytes already in memory; `name` stands for the file in errors.
std::vector<LodLevel> parseLodFile(std::span<const unsigned char> bytes, const std::string& name);

// What a station does at load time with an object's generated levels: use
// `baked` when it holds levels of these ratios made from exactly this mesh
// (its ratio-1 level is the mesh itself); otherwise simplify, and write
// `baked` for next time (a write failure is reported in `note`, the levels
// are still returned). Without a ratio of 1 first there is nothing to know
// the mesh by, and a mesh with vertex colours would lose them in the file:
// such levels are simplified and not saved.
struct LoadedOrSimplified {
    std::vector<LodLevel> levels;
    bool loaded = false;  // false: simplified now
    std::string note;     // what happened and why, naming the file
};
LoadedOrSimplified loadOrSimplifyLevels(const std::filesystem::path& baked, const Geometry& mesh,
                                        std::span<const float> ratios);

}  // namespace arcomp
