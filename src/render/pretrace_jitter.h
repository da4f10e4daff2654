// Where povray 3.7 moves its radiosity pretrace spots within their cells:
// a fixed cycle of 2047 numbers in [-1, 1), through which each pretrace
// tile walks from a starting point set by its pass and its place in the
// image (render/radiosity_pretrace.cpp uses it).
#pragma once

#include <cstddef>
#include <vector>

namespace frameray::render {

class PretraceJitter {
  public:
    static constexpr std::size_t kCycle = 2047;

    // The cycle: the first 2047 outputs of the standard 32-bit Mersenne
    // twister (MT19937, default seed 5489), each u mapped to u / 2^32
    // scaled onto [-1, 1).
    PretraceJitter();

    // A walk through the cycle for pass `pass` (1 for the first pretrace
    // pass) of tile `tile` (row-major number of the 32-pixel tile within
    // the rendered window): it starts after entry (17 pass + 13 tile)
    // mod 2047.
    class Walk {
      public:
        Walk(const PretraceJitter& jitter, int pass, int tile);
        // The next number of the walk (the first is the entry after the
        // starting one).
        double next();

      private:
        const std::vector<double>& values_;
        std::size_t at_;
    };

    double operator[](std::size_t i) const { return values_[i % kCycle]; }

  private:
    std::vector<double> values_;
};

}  // namespace frameray::render
