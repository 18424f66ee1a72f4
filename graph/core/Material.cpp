#include "graph/core/Material.hpp"

#include <cmath>

namespace arcomp {

glm::mat3 TextureTransform::matrix() const {
    // KHR_texture_transform: scale, then rotate, then translate. The sign of
    // the rotation follows the extension's worked example (offset [0, 1],
    // rotation pi/2, scale 0.5 picks the lower-left quadrant) and three.js,
    // not the GLSL snippet beside it, which turns the other way.
    const float c = std::cos(rotation), s = std::sin(rotation);
    const glm::mat3 t(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
    const glm::mat3 r(c, -s, 0, s, c, 0, 0, 0, 1);
    const glm::mat3 sc(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
    return t * r * sc;
}

}  // namespace arcomp
