#include "graph/core/Frustum.hpp"

namespace arcomp {

// Gribb and Hartmann's extraction: each plane is a sum or difference of the
// fourth row of the clip matrix with one of the others (OpenGL clip space).
Frustum Frustum::fromViewProjection(const glm::mat4& m) {
    const glm::vec4 row0{m[0][0], m[1][0], m[2][0], m[3][0]};
    const glm::vec4 row1{m[0][1], m[1][1], m[2][1], m[3][1]};
    const glm::vec4 row2{m[0][2], m[1][2], m[2][2], m[3][2]};
    const glm::vec4 row3{m[0][3], m[1][3], m[2][3], m[3][3]};
    Frustum f;
    f.planes = {row3 + row0, row3 - row0, row3 + row1, row3 - row1, row3 + row2, row3 - row2};
    for (glm::vec4& p : f.planes) p /= glm::length(glm::vec3(p));
    return f;
}

} // namespace arcomp
