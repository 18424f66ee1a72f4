#pragma once
// KHR_draco_mesh_compression: each compressed primitive decoded through
// libdraco into a buffer of arcomp's own, and its accessors pointed at the
// decoded bytes, so that they are read and checked as plain accessors. An
// accessor's declared count and type must match what the decoder produced.
// Internal to graph/io.

#include "graph/io/GltfDocument.hpp"

namespace arcomp::gltf {

// Throws ModelError, at the primitive's extension, for a stream that does
// not decode or decodes to something its accessors do not declare.
void decodeDracoPrimitives(GltfDocument& doc);

}  // namespace arcomp::gltf
