#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "sdl/interpreter.h"

using namespace frameray;
using namespace frameray::sdl;

namespace {

struct Collect : MessageSink {
    std::string text;
    void message(Stream s, const std::string& t) override {
        if (s == Stream::Debug) text += t;
    }
};

struct ParsedText {
    FrameContext ctx;
    TokenCache cache;
    Collect sink;
    Interpreter interp{ctx, cache, sink};
    explicit ParsedText(const std::string& text) { interp.parseText("t.pov", text); }
    double f(const std::string& name) { return std::get<double>(*interp.lookup(name)); }
    VectorValue v(const std::string& name) { return std::get<VectorValue>(*interp.lookup(name)); }
};

}  // namespace

TEST(Expressions, PrecedenceAndFunctions) {
    ParsedText r("#declare A = 1 + 2 * 3 - 4 / 2; #declare B = -2 * (3 + 1); #declare C = pow(2, 10) + abs(-1);"
          "#declare D = (5 > 3 & 2 < 1 | 1); #declare E = (1 ? 7 : 8); #declare F = mod(7, 3) + int(-2.5);");
    EXPECT_EQ(r.f("A"), 5);
    EXPECT_EQ(r.f("B"), -8);
    EXPECT_EQ(r.f("C"), 1025);
    EXPECT_EQ(r.f("D"), 1);
    EXPECT_EQ(r.f("E"), 7);
    EXPECT_EQ(r.f("F"), -1);
}

TEST(Expressions, EqualityUsesEpsilon) {
    ParsedText r("#declare A = (1 = 1 + 1e-12); #declare B = (1 = 1.001);");
    EXPECT_EQ(r.f("A"), 1);
    EXPECT_EQ(r.f("B"), 0);
}

TEST(Expressions, VectorsPromoteAndDotItems) {
    ParsedText r("#declare V = <1,2,3> * 2 + 1; #declare W = <7,6> + <0,0,1>; #declare Y = V.y; #declare S = 2*x + y;");
    EXPECT_EQ(r.v("V").xyz().x, 3);
    EXPECT_EQ(r.v("V").xyz().z, 7);
    EXPECT_EQ(r.v("W").size, 3);
    EXPECT_EQ(r.v("W").v[2], 1);
    EXPECT_EQ(r.f("Y"), 5);
    EXPECT_EQ(r.v("S").xyz().y, 1);
}

TEST(Expressions, ColorsAndPitfalls) {
    ParsedText r("#declare White = rgb 1; #declare G = White * 0.5; #declare C = color red 1 green 0.5;"
          "#declare Cy = color blue 1 green 1; #declare LC = Cy red 0.6; #declare T = rgbt <1,0,0,0.5>;"
          "#declare R = rgb <1,0,0> * 0.5;");
    EXPECT_EQ(r.v("G").v[0], 0.5);
    EXPECT_EQ(r.v("G").v[3], 0);
    EXPECT_EQ(r.v("C").v[1], 0.5);
    EXPECT_EQ(r.v("C").v[2], 0);
    EXPECT_EQ(r.v("LC").v[0], 0.6);
    EXPECT_EQ(r.v("LC").v[1], 1);
    EXPECT_EQ(r.v("T").v[3], 0);
    EXPECT_EQ(r.v("T").v[4], 0.5);
    EXPECT_EQ(r.v("R").v[0], 0.5);
}

TEST(Directives, IfWhileForSwitchMacro) {
    ParsedText r(R"(
        #declare N = 0; #declare I = 0;
        #while (I < 10) #declare N = N + I; #declare I = I + 1; #end
        #declare S = 0;
        #for (K, 1, 4) #declare S = S + K; #end
        #if (S > 100) #declare Z = 1; #elseif (S = 10) #declare Z = 2; #else #declare Z = 3; #end
        #switch (2)
          #case (1) #declare Q = 1; #break
          #range (2, 3) #declare Q = 2;
          #case (4) #declare Q = Q + 10; #break
          #else #declare Q = 99;
        #end
        #macro Twice(A) (2 * A) #end
        #declare M = Twice(Twice(3)) + 1;
        #ifndef (Undefined) #declare U = 1; #end
        #local L = 5; #undef L
    )");
    EXPECT_EQ(r.f("N"), 45);
    EXPECT_EQ(r.f("S"), 10);
    EXPECT_EQ(r.f("Z"), 2);
    EXPECT_EQ(r.f("Q"), 12);
    EXPECT_EQ(r.f("M"), 13);
    EXPECT_EQ(r.f("U"), 1);
    EXPECT_EQ(r.interp.lookup("L"), nullptr);
}

TEST(Directives, DebugAndStrings) {
    ParsedText r(R"(#debug concat("x=", str(1.5, 0, 2), "\n") #declare L = strlen("abc");)");
    EXPECT_EQ(r.sink.text, "x=1.50\n");
    EXPECT_EQ(r.f("L"), 3);
}

TEST(Errors, UndeclaredIdentifierHasLocation) {
    FrameContext ctx;
    TokenCache cache;
    struct : MessageSink { void message(Stream, const std::string&) override {} } sink;
    Interpreter interp(ctx, cache, sink);
    try {
        interp.parseText("s.pov", "#declare A = 1;\nsphere { <0,0,0>, Radius }");
        FAIL();
    } catch (const SdlError& e) {
        EXPECT_EQ(e.loc().line, 2u);
        EXPECT_EQ(e.loc().column, 19u);
        EXPECT_NE(e.message().find("undeclared identifier 'Radius'"), std::string::npos);
    }
}

TEST(Errors, MissingEndAndUnsupported) {
    FrameContext ctx;
    TokenCache cache;
    struct : MessageSink { void message(Stream, const std::string&) override {} } sink;
    EXPECT_THROW(Interpreter(ctx, cache, sink).parseText("s.pov", "#if (1)\n#declare A = 1;\n"), SdlError);
    try {
        Interpreter(ctx, cache, sink).parseText("s.pov", "ovus { 1, 0.5 }");
        FAIL();
    } catch (const SdlError& e) {
        EXPECT_EQ(e.message(), "not supported yet: ovus");
    }
}

TEST(Scene, ObjectsCameraLights) {
    FrameContext ctx;
    TokenCache cache;
    struct : MessageSink { void message(Stream, const std::string&) override {} } sink;
    Interpreter interp(ctx, cache, sink);
    auto scene = interp.parseText("s.pov", R"(
        #declare Ball = sphere { 0, 1 pigment { rgb <1,0,0> } }
        camera { location <0,0,-5> look_at 0 angle 60 }
        light_source { <10,10,-10> color rgb 1 }
        object { Ball translate x }
        plane { y, -1 }
        box { -1, 1 scale 2 }
    )");
    ASSERT_EQ(scene.objects.size(), 3u);
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_NEAR(scene.camera.location.z, -5, 1e-12);
    // angle 60 with right 1.33: direction length 0.5*1.33/tan(30deg).
    EXPECT_NEAR(length(scene.camera.direction), 0.5 * 1.33 / std::tan(M_PI / 6), 1e-12);
    EXPECT_NEAR(scene.objects[0]->transform.point({0, 0, 0}).x, 1, 1e-12);
    EXPECT_EQ(scene.objects[0]->texture->pigment->solidColor().rgb.r, 1);
}

// povray 3.7's numeric edge cases (measured): division by zero warns once
// per component and gives +inf whatever the sign; acos and asin outside
// -1..1 warn and take the nearest end; numbers past double's range read as
// inf or 0.
TEST(Expressions, NumericEdgeCasesAsPovray) {
    struct Warnings : MessageSink {
        std::string text;
        void message(Stream s, const std::string& t) override {
            if (s == Stream::Warning) text += t + "\n";
        }
    };
    FrameContext ctx;
    TokenCache cache;
    Warnings sink;
    Interpreter interp{ctx, cache, sink};
    interp.parseText("t.pov",
                     "#version 3.7;\n#declare A = 1/0;\n#declare B = -1/0;\n#declare C = 0/0;\n"
                     "#declare D = <1,2,3>/0;\n#declare E = acos(2);\n#declare F = asin(-1.5);\n"
                     "#declare G = 1e400;\n#declare H = -1e400;\n#declare I = 1e-400;\n"
                     "#declare J = 1/<0,1,1>;\n");
    const auto f = [&](const std::string& n) { return std::get<double>(*interp.lookup(n)); };
    EXPECT_EQ(f("A"), std::numeric_limits<double>::infinity());
    EXPECT_EQ(f("B"), std::numeric_limits<double>::infinity());
    EXPECT_EQ(f("C"), std::numeric_limits<double>::infinity());
    const VectorValue d = std::get<VectorValue>(*interp.lookup("D"));
    EXPECT_TRUE(std::isinf(d.v[0]) && std::isinf(d.v[1]) && std::isinf(d.v[2]));
    EXPECT_DOUBLE_EQ(f("E"), 0.0);
    EXPECT_DOUBLE_EQ(f("F"), -std::numbers::pi / 2);
    EXPECT_EQ(f("G"), std::numeric_limits<double>::infinity());
    EXPECT_EQ(f("H"), -std::numeric_limits<double>::infinity());
    EXPECT_EQ(f("I"), 0.0);
    // Lines 2-4 once, line 5 three times, line 11 once; acos and asin once each.
    size_t divides = 0;
    for (size_t at = sink.text.find("divide by zero"); at != std::string::npos;
         at = sink.text.find("divide by zero", at + 1))
        ++divides;
    EXPECT_EQ(divides, 7u) << sink.text;
    EXPECT_NE(
        sink.text.find("t.pov:6:14: warning: domain error in acos: 2 is outside -1 to 1; using 1"),
        std::string::npos)
        << sink.text;
    EXPECT_NE(sink.text.find("domain error in asin"), std::string::npos) << sink.text;
    EXPECT_NE(sink.text.find("t.pov:2:15: warning: divide by zero"), std::string::npos)
        << sink.text;
}

// trace() as povray 3.7 answers it (values printed by povray with #debug):
// a surface nearer than 1e-4 to the start is skipped, and the normal of a
// primitive lying inverted in the traced object (a subtracted operand, an
// `inverse` object) is flipped.
TEST(Expressions, TraceSkipsNearHitsAndFlipsInvertedNormals) {
    ParsedText r(
        "#declare S = sphere { 0, 1 }"
        "#declare D = difference { box { -2, 2 } sphere { 0, 1 } }"
        "#declare I = sphere { 0, 1 inverse }"
        "#declare D2 = difference { box { -2, 2 } difference { sphere { 0, 1.5 } sphere { 0, 1 } } }"
        "#declare N1 = <0,0,0>; #declare P1 = trace(S, <0,0,-1.00005>, z, N1);"
        "#declare N2 = <0,0,0>; #declare P2 = trace(S, <0,0,-1.0002>, z, N2);"
        "#declare N3 = <0,0,0>; #declare P3 = trace(D, <0,0,0>, z, N3);"
        "#declare N4 = <0,0,0>; #declare P4 = trace(I, <0,0,-3>, z, N4);"
        "#declare N5 = <0,0,0>; #declare P5 = trace(D2, <0,0,0>, z, N5);"
        "#declare N6 = <0,0,0>; #declare P6 = trace(D2, <0,0,-1.7>, z, N6);");
    EXPECT_DOUBLE_EQ(r.v("P1").xyz().z, 1.0);  // the near front is skipped: the back
    EXPECT_DOUBLE_EQ(r.v("N1").xyz().z, 1.0);
    EXPECT_DOUBLE_EQ(r.v("P2").xyz().z, -1.0);
    EXPECT_DOUBLE_EQ(r.v("N2").xyz().z, -1.0);
    EXPECT_DOUBLE_EQ(r.v("P3").xyz().z, 1.0);
    EXPECT_DOUBLE_EQ(r.v("N3").xyz().z, -1.0);  // the subtracted sphere's
    EXPECT_DOUBLE_EQ(r.v("P4").xyz().z, -1.0);
    EXPECT_DOUBLE_EQ(r.v("N4").xyz().z, 1.0);
    // Subtracted twice: the inner sphere's normal is not flipped.
    EXPECT_DOUBLE_EQ(r.v("P5").xyz().z, 1.0);
    EXPECT_DOUBLE_EQ(r.v("N5").xyz().z, 1.0);
    EXPECT_DOUBLE_EQ(r.v("P6").xyz().z, -1.5);  // subtracted once: flipped
    EXPECT_DOUBLE_EQ(r.v("N6").xyz().z, 1.0);
}
