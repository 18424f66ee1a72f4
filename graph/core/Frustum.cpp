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

// GCC's and Clang's vector extensions: eight lanes, one AVX register or
// two SSE or NEON ones; no intrinsics.
typedef float Float8 __attribute__((vector_size(32)));
typedef std::int32_t Lanes8 __attribute__((vector_size(32)));

}  // namespace

// On x86-64 the loader picks an AVX2 build of this function where the CPU
// has it (half the instructions per sphere) and the SSE2 one elsewhere.
// Not FMA: a fused multiply-add would round differently from classify().
#if defined(__x86_64__) && defined(__GNUC__)  // Clang defines it too
__attribute__((target_clones("avx2", "default")))
#endif
RunContainment
Frustum::classifyRun(const float* x, const float* y, const float* z, const float* radius, std::uint32_t count) const {
    ARCOMP_CHECK(count <= kMaxRun, "a run of at most kMaxRun spheres");
    RunContainment result;
    for (std::uint32_t first = 0; first < count; first += 8) {
        const std::uint32_t lanes = std::min<std::uint32_t>(8, count - first);
        Float8 cx, cy, cz, r;
        if (lanes == 8) {
            std::memcpy(&cx, x + first, sizeof cx);
            std::memcpy(&cy, y + first, sizeof cy);
            std::memcpy(&cz, z + first, sizeof cz);
            std::memcpy(&r, radius + first, sizeof r);
        } else {
            // Lanes past the run hold empty spheres: outside, and masked
            // off below.
            cx = cy = cz = Float8{};
            r = Float8{} - 1.0f;
            for (std::uint32_t i = 0; i < lanes; ++i) {
                cx[i] = x[first + i];
                cy[i] = y[first + i];
                cz[i] = z[first + i];
                r[i] = radius[first + i];
            }
        }
        Lanes8 outside = r < 0.0f;  // empty: never visible
        Lanes8 crossing = Lanes8{};
        for (const glm::vec4& p : planes) {
            const Float8 distance = p.x * cx + p.y * cy + p.z * cz + p.w;
            outside |= distance < -r;
            crossing |= distance < r;
        }
        // Lane i's answer as bit i, without a branch per lane: which spheres
        // are out is as random as where the objects stand.
        const Lanes8 bits{1, 2, 4, 8, 16, 32, 64, 128};
        const Lanes8 out = outside & bits, in = ~(outside | crossing) & bits;
        std::uint32_t outBits = 0, inBits = 0;
        for (int i = 0; i < 8; ++i) {
            outBits |= static_cast<std::uint32_t>(out[i]);
            inBits |= static_cast<std::uint32_t>(in[i]);
        }
        const std::uint32_t laneMask = (1u << lanes) - 1u;
        result.outside |= (outBits & laneMask) << first;
        result.inside |= (inBits & laneMask) << first;
    }
    return result;
}

}  // namespace arcomp
