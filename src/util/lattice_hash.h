// The 4096-entry integer permutation POV-Ray 3.7 hashes lattice points with.
// Its solid noise, its jitter positions for anti-aliasing and several
// patterns index this table, so reproducing POV-Ray's images needs exactly
// this permutation. The table is a pure function of a fixed seed, built at
// compile time: immutable and shared freely between threads.
#pragma once

#include <array>
#include <cstdint>

namespace frameray {

namespace detail {

// POV-Ray's permutation: identity 0..4095, then a backwards Fisher-Yates
// pass whose swap partner comes from the 32-bit linear congruential
// generator state' = state * 1812433253 + 12345 (the same generator as the
// SDL's rand(), starting from state 0), using bits 16..30 of the state
// modulo 4096. The second half repeats the first so that sums of two
// indices need no wrap.
constexpr std::array<std::uint16_t, 8192> makeLatticeHash() {
    std::array<std::uint16_t, 8192> table{};
    for (int i = 0; i < 4096; ++i) table[i] = static_cast<std::uint16_t>(i);
    std::uint32_t state = 0;
    for (int i = 4095; i >= 0; --i) {
        state = state * 1812433253u + 12345u;
        const int j = static_cast<int>((state >> 16) & 0x7FFF) % 4096;
        const std::uint16_t t = table[i];
        table[i] = table[j];
        table[j] = t;
    }
    for (int i = 0; i < 4096; ++i) table[4096 + i] = table[i];
    return table;
}

}  // namespace detail

inline constexpr std::array<std::uint16_t, 8192> kLatticeHash = detail::makeLatticeHash();

}  // namespace frameray
