#include "graph/core/Frustum.hpp"
#include "graph/core/Check.hpp"

#include <algorithm>
#include <cstring>

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

namespace {

// GCC's and Clang's vector extensions: four lanes, one SSE register on every
// x86-64, NEON on ARM; no intrinsics and no build flags.
typedef float Float4 __attribute__((vector_size(16)));
typedef std::int32_t Lanes4 __attribute__((vector_size(16)));

} // namespace

RunContainment Frustum::classifyRun(const float* x, const float* y, const float* z, const float* radius,
                                    std::uint32_t count) const {
    ARCOMP_CHECK(count <= kMaxRun, "a run of at most kMaxRun spheres");
    RunContainment result;
    for (std::uint32_t first = 0; first < count; first += 4) {
        const std::uint32_t lanes = std::min<std::uint32_t>(4, count - first);
        Float4 cx, cy, cz, r;
        if (lanes == 4) {
            std::memcpy(&cx, x + first, sizeof cx);
            std::memcpy(&cy, y + first, sizeof cy);
            std::memcpy(&cz, z + first, sizeof cz);
            std::memcpy(&r, radius + first, sizeof r);
        } else {
            // Lanes past the run hold empty spheres: outside, and masked
            // off below.
            cx = cy = cz = Float4{};
            r = Float4{} - 1.0f;
            for (std::uint32_t i = 0; i < lanes; ++i) {
                cx[i] = x[first + i];
                cy[i] = y[first + i];
                cz[i] = z[first + i];
                r[i] = radius[first + i];
            }
        }
        Lanes4 outside = r < 0.0f;  // empty: never visible
        Lanes4 crossing = Lanes4{};
        for (const glm::vec4& p : planes) {
            const Float4 distance = p.x * cx + p.y * cy + p.z * cz + p.w;
            outside |= distance < -r;
            crossing |= distance < r;
        }
        for (std::uint32_t i = 0; i < lanes; ++i) {
            const std::uint32_t bit = 1u << (first + i);
            if (outside[i]) result.outside |= bit;
            else if (!crossing[i]) result.inside |= bit;
        }
    }
    return result;
}

} // namespace arcomp
