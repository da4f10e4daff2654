// Frame numbers, clocks, output names and render windows. Every expected
// value below was read off povray 3.7 (Debian 3.7.0.10) runs of a scene
// that prints clock, frame_number, clock_delta, clock_on, initial_/final_
// frame and clock, and the files it wrote.
#include "anim/sequence.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "options/options.h"

using namespace frameray;

namespace {

options::RenderOptions withArgs(std::vector<std::string> args) {
    options::RenderOptions o;
    args.insert(args.begin(), "s.pov");
    options::applyArguments(o, args);
    return o;
}

anim::Sequence plan(std::vector<std::string> args) {
    return anim::planSequence(withArgs(std::move(args)));
}

std::vector<int> numbers(const anim::Sequence& s) {
    std::vector<int> out;
    for (const auto& f : s.frames) out.push_back(f.number);
    return out;
}

std::vector<std::string> names(const anim::Sequence& s) {
    std::vector<std::string> out;
    for (const auto& f : s.frames) out.push_back(f.output.string());
    return out;
}

}  // namespace

TEST(Sequence, SingleFrameHasNoNumber) {
    options::RenderOptions o;
    o.inputFile = "dir/scene.pov";
    const auto seq = anim::planSequence(o);
    ASSERT_EQ(seq.frames.size(), 1u);
    EXPECT_EQ(seq.frames[0].output, "scene.png");
    EXPECT_FALSE(seq.animated);
    EXPECT_FALSE(seq.clockOn);
    EXPECT_EQ(seq.frames[0].number, 0);
    EXPECT_EQ(seq.initialFrame, 0);
    EXPECT_EQ(seq.finalFrame, 0);
    EXPECT_EQ(seq.finalClock, 0);
}

TEST(Sequence, WhenPovrayAnimates) {
    // Stills: nothing given, +KFI1 +KFF1, +KFI0, +KFF0, +KFI0 +KFF0.
    for (const auto& args : std::vector<std::vector<std::string>>{{},
                                                                  {"+KFI1", "+KFF1"},
                                                                  {"+KFI0"},
                                                                  {"+KFF0"},
                                                                  {"+KFI0", "+KFF0"},
                                                                  {"+KFF1", "+KFI1"},
                                                                  {"+KC"},
                                                                  {"+KI0.5", "+KF2"}}) {
        const auto s = plan(args);
        EXPECT_FALSE(s.animated) << ::testing::PrintToString(args);
        EXPECT_EQ(names(s), std::vector<std::string>{"s.png"});
    }
    // One-frame animations: numbered file, clock nan, clock_delta inf.
    struct Case {
        std::vector<std::string> args;
        std::string name;
        int number;
    };
    for (const Case& c : std::vector<Case>{{{"+KFF1"}, "s1.png", 1},
                                           {{"+KFI1"}, "s1.png", 1},
                                           {{"+KFI3"}, "s3.png", 3},
                                           {{"+KFI3", "+KFF3"}, "s3.png", 3},
                                           {{"+KFI2", "+KFF2"}, "s2.png", 2},
                                           {{"+KFI-1", "+KFF-1"}, "s0.png", 0},
                                           {{"+KFI5", "+KFF3"}, "s5.png", 5},
                                           {{"+KFI1", "+KFF0"}, "s1.png", 1},
                                           {{"+KFF-1"}, "s1.png", 1},
                                           {{"+KFI0", "+KFF-1"}, "s0.png", 0}}) {
        const auto s = plan(c.args);
        ASSERT_TRUE(s.animated) << ::testing::PrintToString(c.args);
        ASSERT_EQ(s.frames.size(), 1u);
        EXPECT_EQ(s.frames[0].output, c.name);
        EXPECT_EQ(s.frames[0].number, c.number);
        EXPECT_TRUE(std::isnan(s.frames[0].clock));
        EXPECT_TRUE(std::isinf(s.frames[0].clockDelta));
        EXPECT_TRUE(s.clockOn);
    }
    // +KFI0 +KFF1 and +KFI-3 +KFF1: frames 0 and 1.
    EXPECT_EQ(numbers(plan({"+KFI0", "+KFF1"})), (std::vector<int>{0, 1}));
    EXPECT_EQ(numbers(plan({"+KFI-3", "+KFF1"})), (std::vector<int>{0, 1}));
    // Fractions are dropped: +KFI1.6 +KFF3 is frames 1..3.
    EXPECT_EQ(numbers(plan({"+KFI1.6", "+KFF3"})), (std::vector<int>{1, 2, 3}));
}

TEST(Sequence, ClockOnWithClockOption) {
    const auto s = plan({"+K0.7"});
    EXPECT_FALSE(s.animated);
    EXPECT_TRUE(s.clockOn);
    // povray keeps the clock in single precision.
    EXPECT_EQ(s.frames[0].clock, 0.69999998807907104);
    EXPECT_EQ(s.frames[0].clock, static_cast<float>(0.7));
    // In an animation +K is ignored.
    const auto a = plan({"+KFF5", "+K0.7"});
    EXPECT_DOUBLE_EQ(a.frames[0].clock, 0);
    EXPECT_DOUBLE_EQ(a.frames[4].clock, 1);
}

TEST(Sequence, FramesClockAndNamesMatchPovray) {
    auto seq = plan({"+Oout/", "+KFI8", "+KFF12"});
    ASSERT_EQ(seq.frames.size(), 5u);
    EXPECT_EQ(seq.frames[0].output, "out/s08.png");
    EXPECT_EQ(seq.frames[4].output, "out/s12.png");
    EXPECT_EQ(seq.frames[4].log, "out/s12.log");
    EXPECT_DOUBLE_EQ(seq.frames[0].clock, 0);
    EXPECT_DOUBLE_EQ(seq.frames[2].clock, 0.5);
    EXPECT_DOUBLE_EQ(seq.frames[4].clock, 1);
    EXPECT_DOUBLE_EQ(seq.frames[1].clockDelta, 0.25);
    EXPECT_EQ(seq.initialFrame, 8);
    EXPECT_EQ(seq.finalFrame, 12);

    // +KFI5 +KFF12 +KI2 +KF4: delta 2/7.
    seq = plan({"+KFI5", "+KFF12", "+KI2", "+KF4"});
    EXPECT_NEAR(seq.frames[1].clock, 2.285714, 1e-6);
    EXPECT_DOUBLE_EQ(seq.frames[7].clock, 4);
    // Clock running backwards.
    seq = plan({"+KFF5", "+KI1", "+KF0"});
    EXPECT_DOUBLE_EQ(seq.frames[1].clock, 0.75);
    EXPECT_DOUBLE_EQ(seq.frames[1].clockDelta, -0.25);
    // 1..9: one digit; 0..3: one digit.
    EXPECT_EQ(plan({"+KFF9"}).frames[8].output, "s9.png");
    EXPECT_EQ(plan({"+KFI0", "+KFF3"}).frames[0].output, "s0.png");
    EXPECT_EQ(plan({"+KFF9999", "+SF1", "+EF2", "+Oq"}).frames[1].output, "q0002.png");
}

// povray 3.7's clock, printed with str(clock, 0, 20) for each frame: single
// precision, summed from the single-precision start in steps of the
// single-precision range divided in double precision (0.000 before for the
// frames below: frameray's clock was the double-precision value).
TEST(Sequence, ClockIsPovraysSinglePrecisionClock) {
    auto seq = plan({"+KFI1", "+KFF7", "+KI0.1", "+KF0.7"});
    ASSERT_EQ(seq.frames.size(), 7u);
    EXPECT_EQ(seq.frames[1].clock, 0.19999998807907104492);
    EXPECT_EQ(seq.frames[2].clock, 0.29999998211860656738);
    EXPECT_EQ(seq.frames[3].clock, 0.39999997615814208984);
    seq = plan({"+KFI3", "+KFF20", "+KI-1.3", "+KF2.9", "+KC"});
    EXPECT_EQ(seq.frames[1].clock, -1.06666660308837890625);
    EXPECT_EQ(seq.frames[3].clock, -0.59999996423721313477);
    EXPECT_EQ(seq.frames[5].clock, -0.13333334028720855713);
    seq = plan({"+KFF60", "+KC"});
    EXPECT_EQ(seq.frames[1].clock, 0.01666666753590106964);
    EXPECT_EQ(seq.frames[25].clock, 0.41666665673255920410);
    EXPECT_EQ(plan({"+K0.4237"}).frames[0].clock, 0.42370000481605529785);
}

TEST(Sequence, CyclicAnimation) {
    // +KFF10 +KC: frames 1..10, final_frame 11, clock 0 .. 0.9.
    auto seq = plan({"+KFF10", "+KC"});
    ASSERT_EQ(seq.frames.size(), 10u);
    EXPECT_EQ(seq.finalFrame, 11);
    EXPECT_EQ(seq.frames[9].clock, static_cast<float>(0.9));
    EXPECT_DOUBLE_EQ(seq.frames[0].clockDelta, 0.1);
    // +KFF9 +KC: final_frame 10, so names get two digits.
    seq = plan({"+KFF9", "+KC"});
    EXPECT_EQ(seq.frames[0].output, "s01.png");
    EXPECT_EQ(seq.frames.back().output, "s09.png");
    EXPECT_NEAR(seq.frames[1].clock, 0.111111, 1e-6);
    // +KFF2 +KC: 2 frames, clock 0 and 0.5, final_frame 3.
    seq = plan({"+KFF2", "+KC"});
    EXPECT_EQ(numbers(seq), (std::vector<int>{1, 2}));
    EXPECT_DOUBLE_EQ(seq.frames[1].clock, 0.5);
    EXPECT_EQ(seq.finalFrame, 3);
}

TEST(Sequence, Subsets) {
    EXPECT_EQ(numbers(plan({"+KFF10", "+SF3", "+EF5"})), (std::vector<int>{3, 4, 5}));
    EXPECT_NEAR(plan({"+KFF10", "+SF3", "+EF5"}).frames[0].clock, 0.222222, 1e-6);
    // Fractions: floor(f * frame count), as a frame number from 0.
    EXPECT_EQ(numbers(plan({"+KFF10", "+SF0.5"})), (std::vector<int>{5, 6, 7, 8, 9, 10}));
    EXPECT_EQ(numbers(plan({"+KFF10", "+SF0.35", "+EF0.75"})), (std::vector<int>{3, 4, 5, 6, 7}));
    EXPECT_EQ(plan({"+KFF10", "+SF0.05"}).frames.size(), 10u);
    EXPECT_EQ(numbers(plan({"+KFF10", "+SF1.0", "+EF0.999"})).back(), 9);
    EXPECT_EQ(numbers(plan({"+KFI5", "+KFF15", "+SF0.5", "+EF0.8"})),
              (std::vector<int>{5, 6, 7, 8}));
    EXPECT_EQ(numbers(plan({"+KFI5", "+KFF15", "+SF0.33", "+EF0.55"})), (std::vector<int>{5, 6}));
    // Cyclic: the count includes the extra frame.
    EXPECT_EQ(numbers(plan({"+KFF10", "+KC", "+EF0.95"})).back(), 10);
    EXPECT_EQ(numbers(plan({"+KFF10", "+KC", "+SF0.95"})), (std::vector<int>{10}));
    EXPECT_EQ(numbers(plan({"+KFF10", "+KC", "+SF0.5"})).front(), 5);
    // Out of range: start clamps to the initial frame, end to the start;
    // frames past the final frame are rendered, with clocks past 1.
    EXPECT_EQ(numbers(plan({"+KFI5", "+KFF15", "+SF2", "+EF7"})), (std::vector<int>{5, 6, 7}));
    EXPECT_EQ(numbers(plan({"+KFI5", "+KFF15", "+SF9", "+EF7"})), (std::vector<int>{9}));
    EXPECT_EQ(numbers(plan({"+KFF10", "+EF0"})), (std::vector<int>{1}));
    EXPECT_EQ(numbers(plan({"+KFF10", "+SF-3", "+EF-2"})), (std::vector<int>{1}));
    auto seq = plan({"+KFF10", "+SF12"});
    EXPECT_EQ(numbers(seq), (std::vector<int>{12}));
    EXPECT_NEAR(seq.frames[0].clock, 1.222222, 1e-6);
    seq = plan({"+KFI5", "+KFF15", "+SF14", "+EF20"});
    EXPECT_EQ(seq.frames.size(), 7u);
    EXPECT_DOUBLE_EQ(seq.frames.back().clock, 1.5);
}

TEST(Sequence, FrameStep) {
    EXPECT_EQ(numbers(plan({"+KFF10", "Frame_Step=3"})), (std::vector<int>{1, 4, 7, 10}));
    EXPECT_EQ(numbers(plan({"+KFF10", "+STP3"})), (std::vector<int>{1, 4, 7, 10}));
    EXPECT_NEAR(plan({"+KFF10", "+STP3"}).frames[1].clock, 0.333333, 1e-6);
    EXPECT_EQ(numbers(plan({"+KFI3", "+KFF12", "+STP4", "+SF5"})), (std::vector<int>{5, 9}));
    EXPECT_EQ(numbers(plan({"+KFI3", "+KFF12", "+STP4", "+KC"})), (std::vector<int>{3, 7, 11}));
    EXPECT_EQ(numbers(plan({"+KFI3", "+KFF4", "+STP0"})), (std::vector<int>{3, 4}));
}

TEST(Sequence, FieldRenderKeepsFramesAndClocks) {
    // povray 3.7 renders the same frames, clocks and pixels with +UF/+UO.
    const auto a = plan({"+KFF4"});
    const auto b = plan({"+KFF4", "+UF", "+UO"});
    EXPECT_EQ(names(a), names(b));
    EXPECT_DOUBLE_EQ(b.frames[1].clock, a.frames[1].clock);
}

TEST(Sequence, OutputNames) {
    // The extension is dropped only when it is the type's own (case matters).
    EXPECT_EQ(names(plan({"+KFF3", "+Oout.tga"})),
              (std::vector<std::string>{"out.tga1.png", "out.tga2.png", "out.tga3.png"}));
    EXPECT_EQ(names(plan({"+KFF3", "+Oout"})),
              (std::vector<std::string>{"out1.png", "out2.png", "out3.png"}));
    EXPECT_EQ(plan({"+KFF3", "+Oout.jpg", "+FT"}).frames[0].output, "out.jpg1.tga");
    EXPECT_EQ(plan({"+Oout.tga"}).frames[0].output, "out.tga.png");
    EXPECT_EQ(plan({"+Oout.x.y"}).frames[0].output, "out.x.y.png");
    EXPECT_EQ(plan({"+Oout.PNG"}).frames[0].output, "out.PNG.png");
    EXPECT_EQ(plan({"+Oout.jpeg", "+FJ"}).frames[0].output, "out.jpeg.jpg");
    EXPECT_EQ(plan({"+Oout.png"}).frames[0].output, "out.png");
    // A folder only with a trailing slash.
    EXPECT_EQ(plan({"+Osub/"}).frames[0].output, "sub/s.png");
    EXPECT_EQ(plan({"+Osub"}).frames[0].output, "sub.png");
    EXPECT_EQ(names(plan({"+Osub/x.png", "+KFF2"})),
              (std::vector<std::string>{"sub/x1.png", "sub/x2.png"}));
    // A frame number longer than the padding shortens the base name.
    EXPECT_EQ(names(plan({"+KFF15", "+SF99", "+EF101", "+Oabcdef"})),
              (std::vector<std::string>{"abcdef99.png", "abcde100.png", "abcde101.png"}));
    EXPECT_EQ(names(plan({"+KFF15", "+SF99", "+EF101", "+Oab.cd.png"})),
              (std::vector<std::string>{"ab.cd99.png", "ab.c100.png", "ab.c101.png"}));
    EXPECT_EQ(names(plan({"+KFF15", "+SF99", "+EF101"})),
              (std::vector<std::string>{"s99.png", "100.png", "101.png"}));
    // File types.
    EXPECT_EQ(plan({"+FP"}).frames[0].output, "s.ppm");
    EXPECT_EQ(plan({"+FT"}).frames[0].output, "s.tga");
    EXPECT_EQ(plan({"+FC"}).frames[0].output, "s.tga");
    EXPECT_EQ(plan({"+FE"}).frames[0].output, "s.exr");
    EXPECT_EQ(plan({"+FH"}).frames[0].output, "s.hdr");
    EXPECT_EQ(plan({"+FJ"}).frames[0].output, "s.jpg");
    EXPECT_EQ(plan({"+FB"}).frames[0].output, "s.bmp");
    EXPECT_EQ(plan({"+FN16"}).frames[0].output, "s.png");
    // The journal sits beside the images.
    EXPECT_EQ(plan({"+Oframes/demo/", "+KFF3"}).journal, "frames/demo/.s.frameray-journal");
}

TEST(Sequence, RenderWindow) {
    // +W8 +H6 +SR2 +ER4 +SC3 +EC5: povray's "rows 2 to 4, columns 3 to 5".
    auto w = plan({"+W8", "+H6", "+SR2", "+ER4", "+SC3", "+EC5"}).window;
    EXPECT_EQ(w.y0, 1);
    EXPECT_EQ(w.y1, 4);
    EXPECT_EQ(w.x0, 2);
    EXPECT_EQ(w.x1, 5);
    // +W7 +H5 +SR0.5 +ER0.7 +SC0.3 +EC0.5: "rows 3 to 3, columns 3 to 3".
    w = plan({"+W7", "+H5", "+SR0.5", "+ER0.7", "+SC0.3", "+EC0.5"}).window;
    EXPECT_EQ(w.y0, 2);
    EXPECT_EQ(w.y1, 3);
    EXPECT_EQ(w.x0, 2);
    EXPECT_EQ(w.x1, 3);
    // +SR1.0 is row 1, +ER1 the whole height, +EC0.99 column 6 of 7.
    w = plan({"+W7", "+H5", "+SR1.0", "+ER1", "+SC0", "+EC0.99"}).window;
    EXPECT_EQ(w.y0, 0);
    EXPECT_EQ(w.y1, 5);
    EXPECT_EQ(w.x0, 0);
    EXPECT_EQ(w.x1, 6);
    // +ER5.5 is row 5.
    EXPECT_EQ(plan({"+W7", "+H5", "+SR0.1", "+ER5.5"}).window.y1, 5);
    // Empty windows are allowed (+SR3 +ER2 renders nothing).
    w = plan({"+W7", "+H5", "+SR3", "+ER2"}).window;
    EXPECT_GE(w.y0, w.y1);
    EXPECT_TRUE(plan({"+W7", "+H5"}).window.full(7, 5));
    // povray: "Invalid start column or row" / "Invalid end column or row".
    EXPECT_THROW(plan({"+W7", "+H5", "+SR6"}), options::OptionError);
    EXPECT_THROW(plan({"+W7", "+H5", "+SC2", "+EC9"}), options::OptionError);
}

// Frames are computed when asked for: two thousand million of them plan in
// no time and no memory (the frame list used to be built up front and ran
// out of memory), and a subset or shard of them is exact.
TEST(Sequence, HugeAnimationsArePlannedLazily) {
    const auto all = plan({"+KFI1", "+KFF2000000000"});
    ASSERT_EQ(all.frames.size(), 2000000000u);
    EXPECT_EQ(all.frames.front().output, "s0000000001.png");
    EXPECT_EQ(all.frames[1234567].number, 1234568);
    EXPECT_DOUBLE_EQ(all.frames.back().clock, 1.0);
    EXPECT_EQ(all.frames.back().output, "s2000000000.png");
    EXPECT_EQ(all.finalFrame, 2000000000);

    const auto tail = plan({"+KFI1", "+KFF2000000000", "+SF1999999998", "+STP2"});
    EXPECT_EQ(numbers(tail), (std::vector<int>{1999999998, 2000000000}));

    // Shard 2 of 3 of frames 1..2e9: 3, 6, ..., 1999999998.
    const auto shard = plan({"+KFI1", "+KFF2000000000", "+SHC3", "+SHI2"});
    ASSERT_EQ(shard.frames.size(), 666666666u);
    EXPECT_EQ(shard.frames.front().number, 3);
    EXPECT_EQ(shard.frames[1].number, 6);
    EXPECT_EQ(shard.frames.back().number, 1999999998);
    EXPECT_EQ(shard.framesInAllShards, 2000000000u);

    // Cyclic at the largest frame number: final_frame does not overflow.
    const auto cyclic = plan({"+KFI2147483640", "+KFF2147483647", "+KC"});
    EXPECT_EQ(cyclic.frames.size(), 8u);
    EXPECT_EQ(cyclic.frames.back().number, 2147483647);
}

TEST(Sequence, ShardsAreTheSameFramesAsOneRun) {
    const auto whole = plan({"+KFI3", "+KFF40", "+SF5", "+EF33", "+STP3"});
    std::vector<int> merged;
    for (int i = 0; i < 4; ++i) {
        const auto part = plan(
            {"+KFI3", "+KFF40", "+SF5", "+EF33", "+STP3", "+SHC4", "+SHI" + std::to_string(i)});
        for (size_t j = 0; j < part.frames.size(); ++j) {
            const size_t position = j * 4 + static_cast<size_t>(i);
            EXPECT_EQ(part.frames[j].number, whole.frames[position].number);
            EXPECT_EQ(part.frames[j].output, whole.frames[position].output);
            EXPECT_EQ(part.frames[j].clock, whole.frames[position].clock);
            merged.push_back(part.frames[j].number);
        }
    }
    std::sort(merged.begin(), merged.end());
    EXPECT_EQ(merged, numbers(whole));
    // More shards than frames: the last ones are empty.
    EXPECT_TRUE(plan({"+SHC2", "+SHI1"}).frames.empty());
    EXPECT_EQ(plan({"+SHC2", "+SHI0"}).frames.size(), 1u);
}

TEST(Sequence, KnowsItsImageNames) {
    const auto seq = plan({"+KFI3", "+KFF40", "+STP3", "+SHC2", "+SHI1", "+Oout/f"});
    // Frames 3 6 9 ... 39; shard 1 of 2: 6 12 18 ...
    EXPECT_TRUE(seq.frames.holdsImageNamed("f06.png"));
    EXPECT_TRUE(seq.frames.holdsImageNamed("f36.png"));
    EXPECT_FALSE(seq.frames.holdsImageNamed("f03.png"));  // shard 0's
    EXPECT_FALSE(seq.frames.holdsImageNamed("f07.png"));  // not a frame
    EXPECT_FALSE(seq.frames.holdsImageNamed("f42.png"));  // past the end
    EXPECT_FALSE(seq.frames.holdsImageNamed("g06.png"));
    EXPECT_FALSE(seq.frames.holdsImageNamed("f6.png"));
    EXPECT_FALSE(seq.frames.holdsImageNamed("f+6.png"));
    EXPECT_TRUE(plan({}).frames.holdsImageNamed("s.png"));
    EXPECT_FALSE(plan({}).frames.holdsImageNamed("t.png"));
}
