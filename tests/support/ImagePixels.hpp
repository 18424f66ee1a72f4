#pragma once
// Reading a rendered RGBA image the way the render tests check it.

#include "graph/core/Material.hpp"

#include <cstddef>

namespace arcomp::test {

struct Pixel {
    int r, g, b, a;
};

// x from the left, y from the first row stored.
inline Pixel pixelAt(const Image& img, int x, int y) {
    const std::size_t i =
        (static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width) + static_cast<std::size_t>(x)) * 4;
    return {img.rgba[i], img.rgba[i + 1], img.rgba[i + 2], img.rgba[i + 3]};
}

// Pixels anything was drawn to (alpha above zero).
inline std::size_t coveredPixels(const Image& img) {
    std::size_t n = 0;
    for (std::size_t i = 3; i < img.rgba.size(); i += 4) n += img.rgba[i] > 0;
    return n;
}

}  // namespace arcomp::test
