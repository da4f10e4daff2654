// povray 3.7's radiosity pretrace jitter (render/pretrace_jitter.h).
#include "render/pretrace_jitter.h"

#include <gtest/gtest.h>

namespace frameray::render {
namespace {

TEST(PretraceJitter, CycleIsTheTwistersOutputScaledOntoMinusOneToOne) {
    const PretraceJitter jitter;
    // MT19937's first outputs at its default seed 5489 are 3499211612 and
    // 581869302 (the standard's check values start there).
    EXPECT_DOUBLE_EQ(jitter[0], 3499211612.0 / 4294967296.0 * 2 - 1);
    EXPECT_DOUBLE_EQ(jitter[1], 581869302.0 / 4294967296.0 * 2 - 1);
    for (std::size_t i = 0; i < PretraceJitter::kCycle; ++i) {
        EXPECT_GE(jitter[i], -1.0);
        EXPECT_LT(jitter[i], 1.0);
    }
    EXPECT_EQ(jitter[PretraceJitter::kCycle], jitter[0]);  // a cycle of 2047
}

TEST(PretraceJitter, EachPassAndTileWalksFromItsOwnStart) {
    const PretraceJitter jitter;
    PretraceJitter::Walk first(jitter, 1, 0);  // starts after entry 17
    EXPECT_EQ(first.next(), jitter[18]);
    EXPECT_EQ(first.next(), jitter[19]);
    PretraceJitter::Walk later(jitter, 2, 3);  // after 34 + 39 = 73
    EXPECT_EQ(later.next(), jitter[74]);
    PretraceJitter::Walk wraps(jitter, 1, 157);  // (17 + 2041) mod 2047 = 11
    EXPECT_EQ(wraps.next(), jitter[12]);
    PretraceJitter::Walk end(jitter, 0, 0);
    for (std::size_t i = 0; i + 1 < PretraceJitter::kCycle; ++i) end.next();
    EXPECT_EQ(end.next(), jitter[0]);  // the walk goes round
}

}  // namespace
}  // namespace frameray::render
