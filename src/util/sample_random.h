// A small deterministic pseudo-random sequence for per-sample randomness
// (focal blur). Seeded from the sample's image-plane position, so a pixel
// gets the same numbers whatever thread renders it and in whatever order:
// images stay identical across thread counts and frames.
#pragma once

#include <bit>
#include <cstdint>

#include "util/hash.h"

namespace frameray {

class SampleRandom {
  public:
    // Seeds from an image-plane position (and an optional stream number).
    SampleRandom(double x, double y, std::uint64_t stream = 0)
        : state_(splitmix64(std::bit_cast<std::uint64_t>(x) ^
                            splitmix64(std::bit_cast<std::uint64_t>(y) + stream))) {}

    // Uniform in [0, 1).
    double next() { return unitFromHash(nextBits()); }

  private:
    std::uint64_t nextBits() { return splitmix64(state_ += 0x9e3779b97f4a7c15ULL); }

    std::uint64_t state_;
};

}  // namespace frameray
