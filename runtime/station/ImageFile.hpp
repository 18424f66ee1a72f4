#pragma once
// Writing and reading RGBA images as PNG files.
//
//   writePng("out/frame-0001.png", target.read());

#include "graph/core/Material.hpp"

#include <filesystem>

namespace arcomp {

// Creates missing parent folders. Throws std::runtime_error naming the file
// when it cannot be written (disk full, no permission); the file then does
// not exist rather than holding half an image.
void writePng(const std::filesystem::path& file, const Image& image);
// Throws std::runtime_error naming the file when it cannot be read.
Image readPng(const std::filesystem::path& file);

}  // namespace arcomp
