// POV-Ray 3.7's noise_generator 3: a gradient noise on a 2048-cell lattice
// whose unit gradients and permutation come from povray's table generator
// (the 32-bit LCG behind the SDL's rand()). Values reproduce povray's.
#pragma once

#include "util/vec3.h"

namespace frameray::scene {

// The raw gradient noise, about [-0.62, 0.63].
double perlinGradientNoise(const Vec3& p);

// noise_generator 3's scalar noise: the raw value stretched by povray's
// 0.5 * (1.59 n + 0.985) and clamped to [0, 1].
double perlinNoise(const Vec3& p);

}  // namespace frameray::scene
