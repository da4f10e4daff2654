#include "render/pretrace_jitter.h"

#include <random>

namespace frameray::render {

PretraceJitter::PretraceJitter() {
    std::mt19937 twister;  // default seed, as povray 3.7's pretrace uses
    values_.reserve(kCycle);
    constexpr double kSpan = 4294967296.0;  // 2^32: the twister's outputs
    for (std::size_t i = 0; i < kCycle; ++i) {
        const double unit = static_cast<double>(twister()) / kSpan;  // [0, 1)
        values_.push_back(unit * 2.0 - 1.0);
    }
}

PretraceJitter::Walk::Walk(const PretraceJitter& jitter, int pass, int tile)
    : values_(jitter.values_),
      at_((static_cast<std::size_t>(pass) * 17 + static_cast<std::size_t>(tile) * 13) % kCycle) {}

double PretraceJitter::Walk::next() {
    at_ = (at_ + 1) % kCycle;
    return values_[at_];
}

}  // namespace frameray::render
