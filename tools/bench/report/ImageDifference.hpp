#pragma once
// How far a rendered image is from a reference: peak signal-to-noise ratio
// over the RGB channels (alpha ignored), in dB; identical images give
// +infinity. Used to report what a cheaper rendering costs in fidelity.
//
//   double db = psnr(readPng("full.png"), readPng("grouped.png"));

#include "graph/core/Material.hpp"

namespace arcomp {

// Throws std::invalid_argument when the sizes differ.
double psnr(const Image& reference, const Image& test);

}  // namespace arcomp
