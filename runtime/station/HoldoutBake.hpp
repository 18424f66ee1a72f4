#pragma once
// A station's holdout meshes, made at start: every CG mesh of the world,
// each LOD level included, gets its silhouette mesh baked for the box of
// eyes around the camera (paper: silhouette-preserving reduction per
// viewpoint region). A baked mesh is kept in a cache folder and loaded at
// the next start when it still matches the mesh and the region, so a
// station that restarts does not bake again what it baked yesterday.
//
//   const HoldoutBake bake = bakeHoldouts(world, view, cfg.compositing.compositor, folder, cfg.file);   // folder:
//   runtime/station/BakeCache.hpp
//   // world.holdouts now has an entry per mesh node; bake.loaded + bake.baked of them

#include "graph/core/View.hpp"
#include "graph/core/World.hpp"
#include "runtime/config/CompositingConfig.hpp"
#include "runtime/station/BakeCache.hpp"

#include <filesystem>

namespace arcomp {

struct HoldoutBake : BakeTally {
    std::filesystem::path folder;  // empty: no cache, every start bakes
};

// Adds the holdouts to world.holdouts. A mover leaves the region it was
// baked for, so its holdout is its full mesh; so is every holdout with
// `holdout: full`. A skinned mesh's holdout is its own mesh with its skin
// (HoldoutMeshes::addPosed), posed as the CG is. Cached in `cacheFolder`
// (empty: none); `configFile` names the cache files.
HoldoutBake bakeHoldouts(World& world, const View& view, const CompositorConfig& config,
                         const std::filesystem::path& cacheFolder, const std::filesystem::path& configFile);

}  // namespace arcomp
