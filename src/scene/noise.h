// POV-Ray 3.7's solid noise (seed 003 §5.4.1.5): the lattice noise behind
// bozo, granite, marble, wood, agate, wrinkles, bumps and dents, its vector
// form (DNoise) behind turbulence warps and bump normals, and the octave
// sums built on them. Values match povray's to the last bit or two.
#pragma once

#include "util/vec3.h"

namespace frameray::scene {

// noise_generator 1 (original, clipped to [0, 1] often), 2 (range
// corrected, POV-Ray 3.7's default) and 3 (Perlin's).
enum class NoiseGenerator { Original = 1, RangeCorrected = 2, Perlin = 3 };

// Scalar noise in [0, 1].
double solidNoise(const Vec3& p, NoiseGenerator generator);

// Vector noise (POV-Ray's DNoise): each component in about [-1, 1]. Runs
// an AVX2 form where the CPU has it, bit-identical to the portable form.
Vec3 vectorNoise(const Vec3& p);
// The portable form (SSE2 only), for the test that the two agree.
Vec3 vectorNoisePortable(const Vec3& p);

// Turbulence parameters. POV-Ray keeps omega and lambda in single
// precision; the rounding shows in the images, so they are floats here.
struct Turbulence {
    Vec3 amount{0, 0, 0};
    int octaves = 6;
    float omega = 0.5f;
    float lambda = 2.0f;
};

// Sum of `octaves` scalar noises at frequencies lambda^i and weights
// omega^i (marble, agate).
double turbulence(const Vec3& p, const Turbulence& turb, NoiseGenerator generator);

// The same sum of vector noises (turbulence warps, wood).
Vec3 vectorTurbulence(const Vec3& p, const Turbulence& turb);

}  // namespace frameray::scene
