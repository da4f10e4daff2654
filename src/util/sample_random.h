// A small deterministic pseudo-random sequence for per-sample randomness
// (focal blur). Seeded from the sample's image-plane position, so a pixel
// gets the same numbers whatever thread renders it and in whatever order:
// images stay identical across thread counts and frames.
#pragma once

#include <bit>
#include <cstdint>

namespace frameray {

class SampleRandom {
  public:
    // Seeds from an image-plane position (and an optional stream number).
    SampleRandom(double x, double y, std::uint64_t stream = 0)
        : state_(mix(std::bit_cast<std::uint64_t>(x) ^
                     mix(std::bit_cast<std::uint64_t>(y) + stream))) {}

    // Uniform in [0, 1).
    double next() { return static_cast<double>(nextBits() >> 11) * 0x1.0p-53; }

  private:
    // splitmix64: a well-mixed 64-bit sequence from a counter.
    static std::uint64_t mix(std::uint64_t z) {
        z += 0x9e3779b97f4a7c15ULL;
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    std::uint64_t nextBits() { return mix(state_ += 0x9e3779b97f4a7c15ULL); }

    std::uint64_t state_;
};

}  // namespace frameray
