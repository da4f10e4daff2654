#include <gtest/gtest.h>

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
