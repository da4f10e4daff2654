// Stateless 64-bit hashes for deterministic "randomness": jitter, sample
// positions and photon directions are hashed from coordinates and indices,
// so a pixel gets the same numbers whatever thread renders it and in
// whatever order (no shared random-number state between frames or threads).
#pragma once

#include <cstdint>

namespace frameray {

// MurmurHash3's 64-bit finaliser: every input bit affects every output bit.
// Area-light jitter and media sample jitter hash with it.
constexpr std::uint64_t fmix64(std::uint64_t h) {
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdULL;
    h ^= h >> 33;
    h *= 0xc4ceb9fe1a85ec53ULL;
    h ^= h >> 33;
    return h;
}

// splitmix64's step: a well-mixed value from a counter or a seed.
// Sample sequences, photon shooting and rainbow jitter hash with it.
constexpr std::uint64_t splitmix64(std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

// The top 53 bits of a hash as a double uniform in [0, 1).
constexpr double unitFromHash(std::uint64_t h) {
    return static_cast<double>(h >> 11) * 0x1.0p-53;
}

}  // namespace frameray
