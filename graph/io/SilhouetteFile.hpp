#pragma once
// The baked silhouette file: a SilhouetteMesh on disk, so that a station
// loads it instead of baking at start. Little-endian, versioned:
//
//   "ARCSIL\0\0"  u32 version (1)
//   u32 vertexCount  u32 indexCount  u32 regionCount  u32 fullFirst  u32 fullCount
//   f32[3 * vertexCount] positions      u32[indexCount] indices
//   per region: u32 n (4..kMaxRegionVertices)  f32[3 * n] vertices  u32 first  u32 count
//
//   writeSilhouetteFile("bunny.sil", mesh);
//   SilhouetteMesh m = readSilhouetteFile("bunny.sil");
//
// The reader trusts nothing: every count is checked against the bytes left
// before anything is allocated, every index against vertexCount, every range
// against indexCount (and to whole triangles), every float for finiteness,
// and region vertices must span a volume. A bad file throws ModelError
// naming the file, the byte offset and what was expected.

#include "graph/io/ModelError.hpp"
#include "graph/silhouette/SilhouetteMesh.hpp"

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace arcomp {

inline constexpr std::uint32_t kSilhouetteFileVersion = 1;

std::vector<std::byte> encodeSilhouetteMesh(const SilhouetteMesh& mesh);
// `name` only labels errors.
SilhouetteMesh decodeSilhouetteMesh(std::span<const std::byte> bytes, const std::string& name = "<memory>");

void writeSilhouetteFile(const std::filesystem::path& file, const SilhouetteMesh& mesh);
SilhouetteMesh readSilhouetteFile(const std::filesystem::path& file);

// What a station does at load time: use `baked` when it holds exactly this
// mesh (after welding) and these regions; otherwise bake, and write `baked`
// for next time (a write failure is reported in `note`, the mesh is still
// returned).
struct LoadedOrBaked {
    SilhouetteMesh mesh;
    bool loaded = false;  // false: baked now
    std::string note;     // what happened and why, naming the file
};
LoadedOrBaked loadOrBakeSilhouetteMesh(const std::filesystem::path& baked, std::span<const glm::vec3> positions,
                                       std::span<const std::uint32_t> indices, const std::vector<ViewRegion>& regions);

}  // namespace arcomp
