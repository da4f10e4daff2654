// The text object: glyph outlines (even-odd inside, line crossings,
// nearest edge, cubic curves), fonts read through FreeType (character
// maps, metrics, kerning), POV-Ray's layout, the extruded shape, and the
// SDL that makes it (fonts, charsets, CSG).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "parse_support.h"
#include "scene/glyph_outline.h"
#include "scene/text_shape.h"
#include "scene/ttf_font.h"
#include "sdl/interpreter.h"

using namespace frameray;
using namespace frameray::scene;

namespace {

const std::filesystem::path kFontDir = "/usr/share/povray-3.7/include";

bool haveFonts() {
    return std::filesystem::exists(kFontDir / "timrom.ttf");
}

OutlineSegment line(Point2 a, Point2 b) {
    OutlineSegment s;
    s.degree = 1;
    s.p[0] = a;
    s.p[1] = b;
    return s;
}

// A closed polygon, in the given order.
void polygon(std::vector<OutlineSegment>& out, std::initializer_list<Point2> points) {
    const std::vector<Point2> p(points);
    for (size_t i = 0; i < p.size(); ++i) out.push_back(line(p[i], p[(i + 1) % p.size()]));
}

// A unit square with a square hole, both clockwise as in TrueType.
GlyphOutline squareWithHole() {
    std::vector<OutlineSegment> s;
    polygon(s, {{0, 0}, {0, 1}, {1, 1}, {1, 0}});
    polygon(s, {{0.25, 0.25}, {0.25, 0.75}, {0.75, 0.75}, {0.75, 0.25}});
    return GlyphOutline(std::move(s));
}

// A circle of radius r about the origin from four cubic Beziers (CFF style).
GlyphOutline cubicCircle(double r) {
    const double k = 0.5522847498 * r;
    std::vector<OutlineSegment> s;
    const Point2 q[4][4] = {{{r, 0}, {r, k}, {k, r}, {0, r}},
                            {{0, r}, {-k, r}, {-r, k}, {-r, 0}},
                            {{-r, 0}, {-r, -k}, {-k, -r}, {0, -r}},
                            {{0, -r}, {k, -r}, {r, -k}, {r, 0}}};
    for (const auto& c : q) {
        OutlineSegment seg;
        seg.degree = 3;
        std::copy(std::begin(c), std::end(c), seg.p);
        s.push_back(seg);
    }
    return GlyphOutline(std::move(s));
}

std::vector<double> crossings(const GlyphOutline& g, Point2 o, Point2 d) {
    std::vector<double> ts;
    g.lineCrossings(o, d, -1e9, 1e9, ts);
    std::sort(ts.begin(), ts.end());
    return ts;
}

}  // namespace

TEST(GlyphOutline, EvenOddHoles) {
    const GlyphOutline g = squareWithHole();
    EXPECT_TRUE(g.contains(0.1, 0.5));
    EXPECT_TRUE(g.contains(0.9, 0.1));
    EXPECT_FALSE(g.contains(0.5, 0.5));  // in the hole
    EXPECT_FALSE(g.contains(1.5, 0.5));
    EXPECT_FALSE(g.contains(-0.1, 0.5));
    // Through vertices: the half-open rule counts each edge once.
    EXPECT_TRUE(g.contains(0.1, 0.25));
    EXPECT_TRUE(g.contains(0.5, 0.75 + 1e-12));
}

TEST(GlyphOutline, OverlappingContoursCancel) {
    // povray counts crossings: where two outer contours overlap is a hole.
    std::vector<OutlineSegment> s;
    polygon(s, {{0, 0}, {0, 1}, {1, 1}, {1, 0}});
    polygon(s, {{0.5, 0}, {0.5, 1}, {1.5, 1}, {1.5, 0}});
    const GlyphOutline g(std::move(s));
    EXPECT_TRUE(g.contains(0.25, 0.5));
    EXPECT_FALSE(g.contains(0.75, 0.5));
    EXPECT_TRUE(g.contains(1.25, 0.5));
}

TEST(GlyphOutline, LineCrossingsFindEveryWall) {
    const GlyphOutline g = squareWithHole();
    const auto ts = crossings(g, {-1, 0.5}, {1, 0});
    ASSERT_EQ(ts.size(), 4u);
    EXPECT_NEAR(ts[0], 1, 1e-12);
    EXPECT_NEAR(ts[1], 1.25, 1e-12);
    EXPECT_NEAR(ts[2], 1.75, 1e-12);
    EXPECT_NEAR(ts[3], 2, 1e-12);
    // A diagonal line through many bands meets each wall once.
    EXPECT_EQ(crossings(g, {-0.5, -0.4}, {1, 1.1}).size(), 4u);
    EXPECT_TRUE(crossings(g, {-1, 2}, {1, 0}).empty());
}

TEST(GlyphOutline, QuadraticCurves) {
    // An arch: a quadratic from (0,0) over control (1,2) to (2,0), closed
    // by the base line; its top is at y = 1.
    OutlineSegment arch;
    arch.degree = 2;
    arch.p[0] = {0, 0};
    arch.p[1] = {1, 2};
    arch.p[2] = {2, 0};
    const GlyphOutline g({arch, line({2, 0}, {0, 0})});
    EXPECT_TRUE(g.contains(1, 0.99));
    EXPECT_FALSE(g.contains(1, 1.01));
    EXPECT_TRUE(g.contains(0.2, 0.3));  // under the curve at x = 0.2 (y = 0.36)
    EXPECT_FALSE(g.contains(0.2, 0.4));
    const auto ts = crossings(g, {-1, 0.5}, {1, 0});
    ASSERT_EQ(ts.size(), 2u);
    // x(s) where y = 4s(1-s) = 0.5: s = (1 -+ sqrt(0.5))/2, x = 2s.
    EXPECT_NEAR(ts[0], 1 + (1 - std::sqrt(0.5)), 1e-12);
    EXPECT_NEAR(ts[1], 1 + (1 + std::sqrt(0.5)), 1e-12);
}

TEST(GlyphOutline, CubicCurves) {
    const GlyphOutline g = cubicCircle(1);
    EXPECT_TRUE(g.contains(0, 0));
    EXPECT_TRUE(g.contains(0.7, 0.7));
    EXPECT_FALSE(g.contains(0.72, 0.72));
    EXPECT_FALSE(g.contains(1.01, 0));
    const auto ts = crossings(g, {-3, 0.3}, {1, 0});
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_NEAR(ts[0], 3 - std::sqrt(1 - 0.09),
                1e-3);  // the Bezier circle is within 3e-4 of a circle
    EXPECT_NEAR(ts[1], 3 + std::sqrt(1 - 0.09), 1e-3);
}

TEST(GlyphOutline, NearestEdgeGivesTheWallTangent) {
    const GlyphOutline g = squareWithHole();
    Point2 tangent;
    // On the outer left wall (drawn upwards): the left-hand normal (-dy, dx)
    // points out of the glyph.
    EXPECT_NEAR(g.nearestEdge(0, 0.4, tangent), 0, 1e-15);
    EXPECT_LT(-tangent.y, 0);
    EXPECT_NEAR(tangent.x, 0, 1e-15);
    // On the hole's left wall, also drawn upwards: (-dy, dx) points into the
    // hole, out of the solid.
    EXPECT_NEAR(g.nearestEdge(0.25, 0.5, tangent), 0, 1e-15);
    EXPECT_LT(-tangent.y, 0);
    const GlyphOutline c = cubicCircle(1);
    EXPECT_NEAR(c.nearestEdge(0, 1, tangent), 0, 1e-9);
    EXPECT_NEAR(tangent.y, 0, 1e-9);
}

TEST(TextShape, CapsWallsAndHoles) {
    std::vector<PlacedGlyph> glyphs(2);
    glyphs[0].outline = std::make_shared<const GlyphOutline>(squareWithHole());
    glyphs[0].box = {0, 0, 1, 1};
    glyphs[1].outline = glyphs[0].outline;
    glyphs[1].x = 2;  // a second copy, further along x
    glyphs[1].box = {0, 0, 1, 1};
    const TextShape text(std::move(glyphs), 0.5);

    // Straight down z through the solid part: both caps.
    std::vector<double> ts;
    text.allHits({{0.1, 0.5, -2}, {0, 0, 1}}, 0, kInfinity, ts);
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_NEAR(ts[0], 2, 1e-12);
    EXPECT_NEAR(ts[1], 2.5, 1e-12);
    EXPECT_EQ(text.normal({0.1, 0.5, 0}).z, -1);
    EXPECT_EQ(text.normal({0.1, 0.5, 0.5}).z, 1);
    // Through the hole: nothing.
    ts.clear();
    text.allHits({{0.5, 0.5, -2}, {0, 0, 1}}, 0, kInfinity, ts);
    EXPECT_TRUE(ts.empty());
    // Along x in the middle of the thickness: four walls per glyph.
    ts.clear();
    text.allHits({{-1, 0.5, 0.25}, {1, 0, 0}}, 0, kInfinity, ts);
    ASSERT_EQ(ts.size(), 8u);
    EXPECT_NEAR(ts[4], 3, 1e-12);
    const Vec3 n = text.normal({2, 0.5, 0.25});
    EXPECT_NEAR(n.x, -1, 1e-12);
    double first;
    ASSERT_TRUE(text.firstHit({{-1, 0.5, 0.25}, {1, 0, 0}}, 1.5, kInfinity, first));
    EXPECT_NEAR(first, 1.75, 1e-12);
    // Inside: between the caps, in the solid part of either glyph.
    EXPECT_TRUE(text.inside({2.1, 0.5, 0.25}));
    EXPECT_FALSE(text.inside({2.5, 0.5, 0.25}));
    EXPECT_FALSE(text.inside({0.1, 0.5, 0.6}));
    const Bounds b = text.bounds();
    EXPECT_NEAR(b.lo.x, 0, 1e-12);
    EXPECT_NEAR(b.hi.x, 3, 1e-12);
    EXPECT_NEAR(b.hi.z, 0.5 + 1e-6, 1e-12);
}

TEST(TtfFont, MapsMeasuresAndKerns) {
    if (!haveFonts()) GTEST_SKIP() << "POV-Ray's fonts are not installed";
    TtfFont font(kFontDir / "timrom.ttf", TextCharset::Ascii);
    const double em = font.unitsPerEm();
    EXPECT_EQ(em, 1000);
    const TtfFont::Glyph& a = font.glyph(U'A');
    EXPECT_NE(a.index, 0u);
    EXPECT_FALSE(a.outline->empty());
    EXPECT_EQ(&font.glyph(U'A'), &font.glyph(U'A'));  // cached
    // A space is never read: no outline, an empty box, but an advance.
    const TtfFont::Glyph& space = font.glyph(U' ');
    EXPECT_TRUE(space.outline->empty());
    EXPECT_EQ(space.xMin, 0);
    EXPECT_GT(font.advanceWidth(space.metrics), 0);
    // The outline is in em units and its points widen the glyph box.
    const Box2& box = a.outline->box();
    EXPECT_NEAR(box.xlo * em, a.xMin, 1e-9);
    EXPECT_NEAR(box.yhi * em, a.yMax, 1e-9);
    // "AV" and "To" are kerned closer; "AA" is not kerned.
    const unsigned v = font.glyph(U'V').metrics, o = font.glyph(U'o').metrics;
    EXPECT_LT(font.kerning(a.index, v).x, 0);
    EXPECT_LT(font.kerning(font.glyph(U'T').index, o).x, 0);
    EXPECT_EQ(font.kerning(a.index, a.metrics).x, 0);
    EXPECT_THROW(TtfFont(kFontDir / "colors.inc", TextCharset::Ascii), std::runtime_error);
}

TEST(TtfFont, LayoutAsPovray) {
    if (!haveFonts()) GTEST_SKIP() << "POV-Ray's fonts are not installed";
    TtfFont font(kFontDir / "timrom.ttf", TextCharset::Ascii);
    const double em = font.unitsPerEm();
    const auto placed = layoutText(font, U"AV", Vec3(0));
    ASSERT_EQ(placed.size(), 2u);
    // The first glyph's left edge at x = 0.
    EXPECT_NEAR(placed[0].x + placed[0].box.xlo, 0, 1e-12);
    const TtfFont::Glyph& a = font.glyph(U'A');
    const TtfFont::Glyph& v = font.glyph(U'V');
    const double kern = font.kerning(a.index, v.metrics).x;
    const double pen = (font.advanceWidth(a.metrics) - font.leftSideBearing(a.metrics)) / em;
    EXPECT_NEAR(placed[1].x, pen + (font.leftSideBearing(v.metrics) - v.xMin + kern) / em, 1e-12);
    // The offset is added after each character (y too, z never).
    const auto spaced = layoutText(font, U"AVA", Vec3(0.5, 0.25, 9));
    EXPECT_NEAR(spaced[1].x - placed[1].x, 0.5, 1e-12);
    EXPECT_NEAR(spaced[1].y, 0.25, 1e-12);
    EXPECT_NEAR(spaced[2].y, 0.5, 1e-12);
}

// --- SDL ---------------------------------------------------------------------

namespace {

sdl::FrameContext fontContext() {
    sdl::FrameContext c;
    c.libraryPaths = {kFontDir};
    return c;
}

struct Parsed : test_support::ParsedScene {
    explicit Parsed(const std::string& text) : test_support::ParsedScene(text, fontContext()) {}
};

std::string parseError(const std::string& text) {
    return test_support::parseErrorOf(text, fontContext());
}

const TextShape& textOf(const Object& o) {
    const auto* t = dynamic_cast<const TextShape*>(o.shape.get());
    EXPECT_NE(t, nullptr);
    return *t;
}

}  // namespace

TEST(TextSdl, FontsStringsAndModifiers) {
    if (!haveFonts()) GTEST_SKIP() << "POV-Ray's fonts are not installed";
    Parsed p(R"(
        #declare F = "cyrvetic.ttf";
        text { ttf "timrom.ttf" "Hi there" 0.25, 0 pigment { rgb 1 } translate y }
        text { ttf F, concat("A", "B"), 1, <0.1, 0, 0> scale 2 }
        text { internal 3 "mono" 0.1 0 }
        difference { box { -1, 1 } text { ttf "crystal" "x" 1, 0 translate -0.5*z } }
    )");
    ASSERT_EQ(p.scene.objects.size(), 4u);
    // "Hi there": the space has no outline.
    EXPECT_EQ(textOf(*p.scene.objects[0]).glyphCount(), 7u);
    EXPECT_STREQ(p.scene.objects[0]->shape->name(), "text");
    EXPECT_EQ(textOf(*p.scene.objects[1]).glyphCount(), 2u);
    // povray turns text by 0.001 degrees about each axis before its
    // modifiers: the z = 0 cap is not quite flat.
    const Object& hi = *p.scene.objects[0];
    const Vec3 n = hi.normalAt(hi.transform.point({0.1, 0.3, 0}));
    EXPECT_NEAR(n.z, -1, 1e-9);
    EXPECT_NE(n.x, 0);
    EXPECT_TRUE(p.scene.objects[3]->isCsg());
    EXPECT_EQ(p.sink.warnings.find("character"), std::string::npos);
}

TEST(TextSdl, Charsets) {
    if (!haveFonts()) GTEST_SKIP() << "POV-Ray's fonts are not installed";
    {
        // ASCII (the default): each byte of a non-ASCII character becomes
        // a space, with a warning per byte.
        Parsed p("text { ttf \"timrom.ttf\" \"A\xC3\xA9\" 0.1, 0 }");
        EXPECT_EQ(textOf(*p.scene.objects[0]).glyphCount(), 1u);
        EXPECT_NE(p.sink.warnings.find("Non-ASCII character has been replaced by space character."),
                  std::string::npos);
    }
    {
        Parsed p(
            "global_settings { charset utf8 } text { ttf \"timrom.ttf\" \"A\xC3\xA9\" 0.1, 0 }");
        EXPECT_EQ(textOf(*p.scene.objects[0]).glyphCount(), 2u);
        EXPECT_EQ(p.sink.warnings.find("character"), std::string::npos);
    }
    EXPECT_NE(parseError("global_settings { charset sys } text { ttf \"timrom.ttf\" \"A\" 0.1, 0 }")
                  .find("Cannot convert system specific text format to Unicode."),
              std::string::npos);
    EXPECT_NE(parseError("global_settings { charset latin1 }").find("charset type"),
              std::string::npos);
}

TEST(TextSdl, Errors) {
    EXPECT_NE(
        parseError("text { ttf \"no_such_font.ttf\" \"A\" 0.1, 0 }").find("Cannot open font file"),
        std::string::npos);
    EXPECT_NE(
        parseError("text { \"timrom.ttf\" \"A\" 0.1, 0 }").find("expected 'ttf' or 'internal'"),
        std::string::npos);
}
