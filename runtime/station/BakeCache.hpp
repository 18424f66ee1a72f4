#pragma once
// Where a station keeps what it bakes at start, so that a restart loads it
// instead of baking it again: the silhouette meshes of its holdouts (.sil)
// and the generated LOD levels of its objects (.lod). Each file says what it
// was made from, and a stale one is baked again (graph/io/SilhouetteFile.hpp,
// graph/io/LodFile.hpp).
//
//   const std::filesystem::path folder = bakeCacheFolder(cfg.compositing.compositor);
//   const std::filesystem::path file = folder / bakeCacheFileName(cfg.file, "tree", node, ".lod");

#include "runtime/config/CompositingConfig.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

namespace arcomp {

// How a start came by its baked assets.
struct BakeTally {
    std::size_t loaded = 0;  // from the cache
    std::size_t baked = 0;   // now (and saved to the cache, when there is one)
};

// The config's bake_cache; else systemd's CacheDirectory for a service,
// else the user's cache folder. Empty for "none" or when there is no home:
// every start bakes. The folder is created here.
std::filesystem::path bakeCacheFolder(const CompositorConfig& config);

// A file name for one node's baked asset: the config, the node's name and
// id, in characters any file system takes.
std::string bakeCacheFileName(const std::filesystem::path& config, const std::string& node, std::uint32_t id,
                              const char* extension);

}  // namespace arcomp
