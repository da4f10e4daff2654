#include "scene/text_shape.h"

#include <algorithm>
#include <cmath>

#include "scene/ttf_font.h"

namespace frameray::scene {

namespace {

// POV-Ray 3.7's text tolerances (reference data): hits closer than 1e-6
// along the ray are ignored, and a ray direction component below 1e-10
// counts as zero (no caps for a ray parallel to them, no walls for a ray
// along z).
constexpr double kMinDepth = 1e-6;
constexpr double kParallel = 1e-10;

std::vector<double>& scratchHits() {
    // Per-thread scratch for firstHit (a shape query never recurses).
    thread_local std::vector<double> hits;
    hits.clear();
    return hits;
}

}  // namespace

std::vector<PlacedGlyph> layoutText(TtfFont& font, std::u32string_view text, const Vec3& offset) {
    const double unit = 1.0 / font.unitsPerEm();
    std::vector<PlacedGlyph> placed;
    placed.reserve(text.size());
    // The pen: where the next glyph's origin goes, before its bearing.
    double penX = 0, penY = 0;
    unsigned previous = 0;
    for (size_t i = 0; i < text.size(); ++i) {
        const TtfFont::Glyph& g = font.glyph(text[i]);
        const int advance = font.advanceWidth(g.metrics);
        const int bearing = font.leftSideBearing(g.metrics);
        PlacedGlyph p;
        if (i == 0) {
            // The first glyph starts at x = 0: its left side bearing dropped.
            p.x = -g.xMin * unit;
            penX = (advance - bearing) * unit;
            penY = 0;
        } else {
            const TtfFont::Kerning kern = font.kerning(previous, g.metrics);
            p.x = penX + (bearing - g.xMin + kern.x) * unit;
            p.y = penY + kern.y * unit;
            penX += (advance + kern.x) * unit;
        }
        penX += offset.x;
        penY += offset.y;
        p.outline = g.outline;
        p.box = {g.xMin * unit, g.yMin * unit, g.xMax * unit, g.yMax * unit};
        placed.push_back(std::move(p));
        previous = g.index;
    }
    return placed;
}

TextShape::TextShape(const std::vector<PlacedGlyph>& glyphs, double thickness)
    : thickness_(thickness), zLo_(std::min(0.0, thickness)), zHi_(std::max(0.0, thickness)) {
    for (const PlacedGlyph& p : glyphs) {
        // povray's bounds: each glyph's box, a hair thicker than the text.
        bounds_.extend(Vec3(p.box.xlo + p.x, p.box.ylo + p.y, zLo_ - kMinDepth));
        bounds_.extend(Vec3(p.box.xhi + p.x, p.box.yhi + p.y, zHi_ + kMinDepth));
        if (!p.outline || p.outline->empty()) continue;
        const Box2& c = p.outline->box();
        const Bounds box{{c.xlo + p.x, c.ylo + p.y, zLo_}, {c.xhi + p.x, c.yhi + p.y, zHi_}};
        bounds_.extend(box);
        glyphs_.push_back({p.outline, p.x, p.y, box.padded()});
    }
}

void TextShape::glyphHits(const Glyph& g, const Ray& ray, double tMin, double tMax,
                          std::vector<double>& ts) const {
    const double lo = std::max(tMin, kMinDepth);
    double ta = lo, tb = tMax;
    if (!g.box.clip(ray, ta, tb)) return;
    const Vec3 o{ray.origin.x - g.dx, ray.origin.y - g.dy, ray.origin.z};
    const Vec3& d = ray.direction;
    const GlyphOutline& outline = *g.outline;

    // Caps: where the ray meets z = 0 and z = thickness inside the outline.
    if (std::fabs(d.z) >= kParallel) {
        const double t0 = -o.z / d.z;
        const double t1 = t0 + thickness_ / d.z;
        for (const double t : {t0, t1})
            if (t > lo && t < tMax && outline.contains(o.x + t * d.x, o.y + t * d.y))
                ts.push_back(t);
    }

    // Walls: where the ray's shadow on the xy plane crosses the outline,
    // between the caps.
    if (std::fabs(d.x) < kParallel && std::fabs(d.y) < kParallel) return;
    const size_t from = ts.size();
    outline.lineCrossings({o.x, o.y}, {d.x, d.y}, ta, tb, ts);
    size_t kept = from;
    for (size_t i = from; i < ts.size(); ++i) {
        const double t = ts[i];
        const double z = o.z + t * d.z;
        if (z >= 0 && z <= thickness_ && t > lo && t < tMax) ts[kept++] = t;
    }
    ts.resize(kept);
}

bool TextShape::RaySpan::misses(const Bounds& b) const {
    return b.hi.x < lo.x || b.lo.x > hi.x || b.hi.y < lo.y || b.lo.y > hi.y;
}

// Where the ray runs inside the text's bounds, as an xy rectangle: glyphs
// outside it need no slab test. A ray seen from the front crosses the thin
// text in a short span, so it meets one or two glyphs of a long line.
bool TextShape::span(const Ray& ray, double tMin, double tMax, RaySpan& s) const {
    double ta = std::max(tMin, kMinDepth), tb = tMax;
    if (!bounds_.clip(ray, ta, tb)) return false;
    const Vec3 a = ray.origin + ray.direction * ta, b = ray.origin + ray.direction * tb;
    s.lo = {std::min(a.x, b.x), std::min(a.y, b.y)};
    s.hi = {std::max(a.x, b.x), std::max(a.y, b.y)};
    return true;
}

void TextShape::allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const {
    const size_t from = ts.size();
    RaySpan s;
    if (!span(ray, tMin, tMax, s)) return;
    for (const Glyph& g : glyphs_)
        if (!s.misses(g.box)) glyphHits(g, ray, tMin, tMax, ts);
    std::sort(ts.begin() + static_cast<std::ptrdiff_t>(from), ts.end());
}

bool TextShape::firstHit(const Ray& ray, double tMin, double tMax, double& t) const {
    RaySpan s;
    if (!span(ray, tMin, tMax, s)) return false;
    std::vector<double>& hits = scratchHits();
    bool found = false;
    for (const Glyph& g : glyphs_) {
        if (s.misses(g.box)) continue;
        hits.clear();
        // Later glyphs only matter nearer than the best hit so far.
        glyphHits(g, ray, tMin, tMax, hits);
        for (const double h : hits) {
            if (h < tMax) {
                tMax = h;
                found = true;
            }
        }
    }
    if (found) t = tMax;
    return found;
}

Vec3 TextShape::normal(const Vec3& p) const {
    // The surface nearest p among the glyphs whose box holds it: a cap
    // (facing -z at z = 0, +z at z = thickness) or a wall, whose normal is
    // the outline's left-hand normal, as povray computes it.
    double best = kInfinity;
    Vec3 n(0, 0, -1);
    for (const Glyph& g : glyphs_) {
        const Bounds& b = g.box;
        constexpr double kSlack = 1e-6;
        if (p.x < b.lo.x - kSlack || p.x > b.hi.x + kSlack || p.y < b.lo.y - kSlack ||
            p.y > b.hi.y + kSlack || p.z < b.lo.z - kSlack || p.z > b.hi.z + kSlack)
            continue;
        const double bottom = std::fabs(p.z), top = std::fabs(p.z - thickness_);
        if (bottom < best) {
            best = bottom;
            n = Vec3(0, 0, -1);
        }
        if (top < best) {
            best = top;
            n = Vec3(0, 0, 1);
        }
        Point2 tangent;
        const double wall = g.outline->nearestEdge(p.x - g.dx, p.y - g.dy, tangent);
        if (wall < best) {
            best = wall;
            n = normalize(Vec3(-tangent.y, tangent.x, 0));
        }
    }
    return n;
}

bool TextShape::inside(const Vec3& p) const {
    if (!(p.z >= 0 && p.z <= thickness_)) return false;
    for (const Glyph& g : glyphs_) {
        const Bounds& b = g.box;
        if (p.x < b.lo.x || p.x > b.hi.x || p.y < b.lo.y || p.y > b.hi.y) continue;
        if (g.outline->contains(p.x - g.dx, p.y - g.dy)) return true;
    }
    return false;
}

}  // namespace frameray::scene
