// Resource limits of the interpreter (FrameContext::Limits): each ends the
// parse with an error at the place that went past it, before the stack,
// the memory or the time runs out. The limits are lowered here so the tests
// stay small; tests/language/errors/limit_*.pov check the default ones.
#include <gtest/gtest.h>

#include <thread>

#include "parse_support.h"

namespace frameray {
namespace {

using test_support::parseErrorOf;

sdl::FrameContext withLimits(void (*set)(sdl::FrameContext::Limits&)) {
    sdl::FrameContext ctx;
    set(ctx.limits);
    return ctx;
}

TEST(Limits, ArraysMadeInAFrameAreCountedTogether) {
    const auto ctx = withLimits([](auto& l) {
        l.arrayElements = 100;
        l.totalArrayElements = 250;
    });
    EXPECT_EQ(parseErrorOf("#declare A = array[100]; #declare B = array[100];", ctx), "");
    // Copies count too: the third hundred is one too many.
    const std::string copy =
        parseErrorOf("#declare A = array[100]; #declare B = A; #declare C = A;", ctx);
    EXPECT_NE(copy.find("t.pov:1:"), std::string::npos) << copy;
    EXPECT_NE(copy.find("arrays made in this frame hold more than 250 elements in all"),
              std::string::npos)
        << copy;
    // Re-declaring in a loop adds up as well.
    EXPECT_NE(parseErrorOf("#for (I, 1, 3) #declare A = array[100]; #end", ctx).find("in all"),
              std::string::npos);
}

TEST(Limits, OneArrayAndItsDimensions) {
    const auto ctx = withLimits([](auto& l) { l.arrayElements = 1000; });
    EXPECT_EQ(parseErrorOf("#declare A = array[10][10][10];", ctx), "");
    EXPECT_NE(parseErrorOf("#declare A = array[10][10][11];", ctx)
                  .find("array of more than 1000 elements"),
              std::string::npos);
    // Sizes with no integer value are refused, not converted.
    for (const char* size : {"1e300", "-1e300", "0", "-1"})
        EXPECT_NE(parseErrorOf(std::string("#declare A = array[") + size + "];", ctx), "") << size;
    EXPECT_NE(
        parseErrorOf("#declare A = array[5]; #declare B = A[1e300];", ctx).find("out of range"),
        std::string::npos);
}

TEST(Limits, StringLength) {
    const auto ctx = withLimits([](auto& l) { l.stringLength = 64; });
    EXPECT_EQ(parseErrorOf("#declare S = concat(\"0123456789\", \"0123456789\");", ctx), "");
    const std::string e =
        parseErrorOf("#declare S = \"01234567\"; #while (1) #declare S = concat(S, S); #end", ctx);
    EXPECT_NE(e.find("string of 128 bytes is longer than the limit of 64"), std::string::npos) << e;
    EXPECT_NE(parseErrorOf("#declare S = str(1, 100, 0);", ctx).find("longer than the limit"),
              std::string::npos);
    EXPECT_NE(parseErrorOf("#declare S = vstr(3, <1,2,3>, \",\", 0, 30);", ctx)
                  .find("longer than the limit"),
              std::string::npos);
}

TEST(Limits, ParseIterationsCountLoopsAndMacroCalls) {
    const auto ctx = withLimits([](auto& l) { l.parseIterations = 50; });
    EXPECT_EQ(parseErrorOf("#for (I, 1, 40) #end", ctx), "");
    EXPECT_NE(parseErrorOf("#for (I, 1, 60) #end", ctx).find("Max_Parse_Iterations"),
              std::string::npos);
    EXPECT_NE(parseErrorOf("#while (1) #end", ctx).find("t.pov:1:2:"), std::string::npos);
    EXPECT_NE(parseErrorOf("#macro M() 1 #end #for (I, 1, 30) #declare X = M(); #end", ctx)
                  .find("Max_Parse_Iterations"),
              std::string::npos);
    // 0: no limit.
    const auto unlimited = withLimits([](auto& l) { l.parseIterations = 0; });
    EXPECT_EQ(parseErrorOf("#for (I, 1, 1000) #end", unlimited), "");
}

TEST(Limits, NestingOfEveryKind) {
    const auto ctx = withLimits([](auto& l) { l.nesting = 50; });
    auto nested = [](const std::string& open, const std::string& middle, const std::string& close,
                     int n) {
        std::string s;
        for (int i = 0; i < n; ++i) s += open;
        s += middle;
        for (int i = 0; i < n; ++i) s += close;
        return s;
    };
    const std::string tooDeep = "nested too deeply: more than 50 levels";
    EXPECT_EQ(parseErrorOf("#declare A = " + nested("(", "1", ")", 40) + ";", ctx), "");
    EXPECT_NE(parseErrorOf("#declare A = " + nested("(", "1", ")", 60) + ";", ctx).find(tooDeep),
              std::string::npos);
    EXPECT_NE(parseErrorOf("#declare A = " + nested("-", "1", "", 60) + ";", ctx).find(tooDeep),
              std::string::npos);
    EXPECT_NE(parseErrorOf(nested("union { sphere { 0, 1 } ", "", "}", 60), ctx).find(tooDeep),
              std::string::npos);
    EXPECT_NE(parseErrorOf("#declare F = function { " + nested("(", "x", ")", 60) + " };", ctx)
                  .find(tooDeep),
              std::string::npos);
    EXPECT_NE(parseErrorOf("#declare A = array[2] { " + nested("(", "1", ")", 60) + ", 1 };", ctx)
                  .find(tooDeep),
              std::string::npos);
}

TEST(Limits, DeepNestingOnASmallStackStopsCleanly) {
    // A thread whose stack is smaller than the nesting limit assumes: the
    // stack check ends the parse before it overflows.
    std::string error;
    std::thread worker([&] {
        sdl::FrameContext ctx;
        ctx.limits.nesting = 1'000'000;
        std::string text = "#declare A = ";
        for (int i = 0; i < 100000; ++i) text += '(';
        error = parseErrorOf(text + "1;", ctx);
    });
    worker.join();
    EXPECT_NE(error.find("the parser's stack is exhausted"), std::string::npos)
        << error.substr(0, 200);
}

}  // namespace
}  // namespace frameray
