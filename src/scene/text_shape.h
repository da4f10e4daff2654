// The text object: a string of glyph outlines extruded from z = 0 to
// z = thickness, laid out along +x in em units (1 unit = the font's em),
// as POV-Ray 3.7 builds it.
//
// povray makes each character its own shape and the text a union of them;
// TextShape holds them all behind one transform, with the union's rules:
// every glyph's surface is kept (where glyphs overlap, their inner walls
// remain), and a point is inside when it is inside any glyph. Within a
// glyph, holes follow the even-odd rule (GlyphOutline).
//
// A glyph's surface is its two caps (the outline's inside at z = 0 and at
// z = thickness) and its walls (the outline swept along z). Each glyph has
// its own box, so a ray only looks at the glyphs it passes near, and the
// outline's bands keep it to the curves near its path.
#pragma once

#include <memory>
#include <string_view>
#include <vector>

#include "scene/glyph_outline.h"
#include "scene/shapes.h"

namespace frameray::scene {

class TtfFont;

// A glyph outline placed in the string: shifted by (x, y). `box` is the
// glyph's box as povray computes it (its bounds), in em units, unshifted.
struct PlacedGlyph {
    std::shared_ptr<const GlyphOutline> outline;
    double x = 0, y = 0;
    Box2 box;
};

// Lays out characters as POV-Ray 3.7 does: the first glyph's left edge at
// x = 0; each next one placed by the previous advance width, its left side
// bearing and the kern pair; `offset` added after every character (its z
// has no effect, as in povray).
std::vector<PlacedGlyph> layoutText(TtfFont& font, std::u32string_view text, const Vec3& offset);

class TextShape final : public Shape {
  public:
    TextShape(const std::vector<PlacedGlyph>& glyphs, double thickness);

    void allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const override;
    bool firstHit(const Ray& ray, double tMin, double tMax, double& t) const override;
    Vec3 normal(const Vec3& p) const override;
    bool inside(const Vec3& p) const override;
    Bounds bounds() const override { return bounds_; }
    const char* name() const override { return "text"; }

    size_t glyphCount() const { return glyphs_.size(); }

  private:
    struct Glyph {
        std::shared_ptr<const GlyphOutline> outline;
        double dx, dy;
        Bounds box;  // where its surface can be, in text space
    };
    // The xy rectangle the ray covers inside the text's bounds: glyphs
    // whose boxes miss it cannot be hit.
    struct RaySpan {
        Point2 lo, hi;
        bool misses(const Bounds& b) const;
    };
    bool span(const Ray& ray, double tMin, double tMax, RaySpan& s) const;
    // Every crossing of glyph g in (tMin, tMax), appended to ts.
    void glyphHits(const Glyph& g, const Ray& ray, double tMin, double tMax,
                   std::vector<double>& ts) const;

    std::vector<Glyph> glyphs_;  // only glyphs with an outline
    double thickness_;
    double zLo_, zHi_;
    Bounds bounds_;
};

}  // namespace frameray::scene
