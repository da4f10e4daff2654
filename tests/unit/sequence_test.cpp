#include <gtest/gtest.h>

#include "anim/sequence.h"

using namespace frameray;

TEST(Sequence, SingleFrameHasNoNumber) {
    options::RenderOptions o;
    o.inputFile = "dir/scene.pov";
    const auto seq = anim::planSequence(o);
    ASSERT_EQ(seq.frames.size(), 1u);
    EXPECT_EQ(seq.frames[0].output, "scene.png");
    EXPECT_FALSE(seq.frames[0].animated);
}

TEST(Sequence, FramesClockAndNamesMatchPovray) {
    options::RenderOptions o;
    o.inputFile = "scene.pov";
    o.outputFile = "out/";
    o.initialFrame = 8;
    o.finalFrame = 12;
    o.initialClock = 0;
    o.finalClock = 1;
    auto seq = anim::planSequence(o);
    ASSERT_EQ(seq.frames.size(), 5u);
    EXPECT_EQ(seq.frames[0].output, "out/scene08.png");
    EXPECT_EQ(seq.frames[4].output, "out/scene12.png");
    EXPECT_EQ(seq.frames[4].log, "out/scene12.log");
    EXPECT_DOUBLE_EQ(seq.frames[0].clock, 0);
    EXPECT_DOUBLE_EQ(seq.frames[2].clock, 0.5);
    EXPECT_DOUBLE_EQ(seq.frames[4].clock, 1);
    EXPECT_DOUBLE_EQ(seq.frames[1].clockDelta, 0.25);

    o.cyclicAnimation = true;  // the clock stops one step before final_clock
    seq = anim::planSequence(o);
    EXPECT_DOUBLE_EQ(seq.frames[4].clock, 0.8);

    o.outputFile = "x.png";
    o.finalFrame = 9;
    o.cyclicAnimation = false;
    seq = anim::planSequence(o);
    EXPECT_EQ(seq.frames[0].output, "x8.png");
}
