// The 4096-entry integer permutation POV-Ray 3.7 hashes lattice points with.
// Its solid noise, its jitter positions for anti-aliasing and several
// patterns index this table, so reproducing POV-Ray's images needs exactly
// this permutation. The table is a pure function of a fixed seed, built at
// compile time: immutable and shared freely between threads.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

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

// POV-Ray's hash of an integer lattice point (each coordinate's low 12
// bits, two's complement).
constexpr int latticeHash3(int a, int b, int c) {
    return kLatticeHash[kLatticeHash[kLatticeHash[a & 0xFFF] ^ (b & 0xFFF)] ^ (c & 0xFFF)];
}

// A coordinate truncated to a lattice index as x86 truncation does it: a
// value beyond int's range, or NaN, gives INT_MIN (what POV-Ray's and our
// own builds computed; the plain C++ conversion is undefined there, and a
// far fog or a huge scale reaches it).
constexpr int latticeTruncate(double v) {
    return v > -2147483649.0 && v < 2147483648.0 ? static_cast<int>(v)
                                                 : std::numeric_limits<int>::min();
}

// floor(v) as a cell index for patterns that visit neighbouring cells
// (index +- 2): kept within +-2^30 so those sums cannot overflow; NaN gives
// 0. Far out there, every cell is as good as another.
inline int latticeFloor(double v) {
    constexpr double kLimit = 1073741824.0;  // 2^30
    if (!(v > -kLimit)) return v != v ? 0 : -static_cast<int>(kLimit);
    if (!(v < kLimit)) return static_cast<int>(kLimit);
    return static_cast<int>(std::floor(v));
}

}  // namespace frameray
