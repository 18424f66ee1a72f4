#pragma once
// What the renderer's top shading levels need from an Environment, worked
// out once on the CPU when the environment is set (well under a second for
// the sizes used here):
//
//   ImageBasedLight ibl = prefilterEnvironment(neutralEnvironment());
//   SplitSumTable lut = splitSumTable();   // once per process, environment-free
//
// - diffuse: the irradiance E(n) as Ramamoorthi & Hanrahan's quadratic form
//   (2001, "An efficient representation for irradiance environment maps",
//   eq. 11-12) from 9 spherical-harmonic coefficients: per colour channel a
//   symmetric 4x4 matrix M with E(n)/pi = (n,1)^T M (n,1), so the shader
//   needs one matrix product and no basis functions;
// - specular: the environment prefiltered with the GGX lobe for a ladder of
//   roughnesses, level i for roughness i / (levels - 1), each half the size
//   of the one before, to be sampled as the mip levels of one equirectangular
//   texture (Karis 2013, "Real Shading in Unreal Engine 4", split sum, first
//   factor, with n = v = r);
// - the split sum's second factor, the environment BRDF, as a table over
//   (n.v, roughness): F0 * scale + bias.

#include "runtime/render/Environment.hpp"

#include <array>
#include <vector>

namespace arcomp {

struct ImageBasedLight {
    std::array<glm::mat4, 3> irradiance{};  // r, g, b: E(n)/pi = dot(n4, M * n4), n4 = (n, 1)
    std::vector<Environment> specular;      // roughness 0 first; each level half the previous size
};

// `size`: the width of the sharpest specular level (a power of two).
ImageBasedLight prefilterEnvironment(const Environment& environment, int size = 128, int levels = 5);

// Irradiance over pi for a unit normal, from the matrices above (for tests
// and for checking the shader against the CPU).
glm::vec3 diffuseRadiance(const ImageBasedLight& light, const glm::vec3& normal);

struct SplitSumTable {
    int size = 0;
    std::vector<glm::vec2> scaleBias;  // row: roughness (0 at row 0), column: n.v; texel centres
};
SplitSumTable splitSumTable(int size = 32);

}  // namespace arcomp
