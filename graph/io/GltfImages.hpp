#pragma once
// A glTF document's images decoded to RGBA8: PNG and JPEG through
// tinygltf's stb_image, WebP (EXT_texture_webp) through libwebp. An image
// that does not decode costs its texture, not the model: it is left empty,
// with a warning that says why. A URI that leads outside the model's
// folder is a ModelError, as for buffers. Internal to graph/io.

#include "graph/core/Material.hpp"
#include "graph/io/GltfDocument.hpp"

#include <string>
#include <vector>

namespace arcomp::gltf {

std::vector<Image> readGltfImages(GltfDocument& doc, std::vector<std::string>& warnings);

}  // namespace arcomp::gltf
