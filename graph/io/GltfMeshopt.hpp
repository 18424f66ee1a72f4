#pragma once
// EXT_meshopt_compression: each compressed buffer view decoded, through
// meshoptimizer's decoders, into the bytes the view covers in its own
// (usually fallback) buffer, so that accessors read it as a plain view.
// Internal to graph/io.

#include "graph/io/GltfDocument.hpp"

namespace arcomp::gltf {

// Throws ModelError, at the view's extension, for a stream that does not
// decode or a view too short for what it declares.
void decodeMeshoptViews(GltfDocument& doc);

}  // namespace arcomp::gltf
