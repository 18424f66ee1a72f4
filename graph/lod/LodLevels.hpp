#pragma once
// Generated LOD levels: a mesh simplified to given fractions of its
// triangles with meshoptimizer, for `arcomp bake lod` and for models that
// bring no levels of their own.
//
//   std::vector<LodLevel> levels = simplifyLevels(g, {1.0f, 0.25f, 0.05f});
//   // levels[1].geometry.triangleCount() is about a quarter of g's
//   NodeId lod = addGeneratedLod(scene, lods, parent, part, {1.0f, 0.25f, 0.05f}, settings);
//
// Simplification works on positions alone (vertices split at UV or normal
// seams count as one), so seams do not stop it; every kept vertex is one of
// the original vertices with its own normal and UV, so attributes stay
// those of the surface they came from.

#include "graph/core/Scene.hpp"
#include "graph/lod/Lod.hpp"

#include <span>
#include <vector>

namespace arcomp {

struct LodLevel {
    Geometry geometry;
    float ratio = 1.0f;  // requested fraction of the original triangles
    float error = 0.0f;  // geometric deviation, in the model's units
};

// One level per ratio, each simplified from `g` itself. Ratios must lie in
// (0, 1]; 1 keeps the mesh as it is. Where edge collapses stall above the
// target (meshoptimizer cannot collapse further within topology), a sloppy
// pass (vertex clustering) reaches it instead.
std::vector<LodLevel> simplifyLevels(const Geometry& g, std::span<const float> ratios);

// Levels for a model that has none: simplifies the part's geometry, adds the
// levels as geometries, and puts an LOD node (with `settings`) over one mesh
// per level under `parent`. settings' thresholds must match ratios.size().
NodeId addGeneratedLod(Scene& scene, LodTable& lods, NodeId parent, MeshPart part, std::span<const float> ratios,
                       const LodNode& settings);
// The same with levels made before (simplifyLevels, or read back from a
// .lod file); a level of ratio 1 draws the part's own geometry.
NodeId addLodLevels(Scene& scene, LodTable& lods, NodeId parent, MeshPart part, std::vector<LodLevel> levels,
                    const LodNode& settings);

}  // namespace arcomp
