// Shapes built from numbers swept or searched in space: superellipsoid,
// isosurface, lathe, sor, prism and sphere_sweep (seed 000 §3.4). Each
// parser starts after the shape's '{' and stops before its modifiers.
#include <fmt/format.h>

#include <cmath>

#include "scene/isosurface.h"
#include "scene/parametric.h"
#include "scene/prism.h"
#include "scene/sphere_sweep.h"
#include "scene/spline_revolution.h"
#include "scene/superellipsoid.h"
#include "sdl/builders.h"
#include "sdl/function_value.h"

namespace frameray::sdl {

// The optional spline kind of a lathe or prism; linear when absent.
static bool acceptSplineKind(Keyword kw, scene::SplineKind& kind) {
    switch (kw) {
        case Keyword::kw_linear_spline:
            kind = scene::SplineKind::Linear;
            return true;
        case Keyword::kw_quadratic_spline:
            kind = scene::SplineKind::Quadratic;
            return true;
        case Keyword::kw_cubic_spline:
            kind = scene::SplineKind::Cubic;
            return true;
        case Keyword::kw_bezier_spline:
            kind = scene::SplineKind::Bezier;
            return true;
        default:
            return false;
    }
}

std::shared_ptr<const scene::Shape> parseLathe(BuildContext& c, const Token& kind) {
    Reader& r = c.reader;
    scene::SplineKind spline = scene::SplineKind::Linear;
    if (acceptSplineKind(r.peek().kw, spline)) r.next();
    const Token countAt = r.peek();
    const int count = static_cast<int>(r.parseFloat());
    const int minimum = scene::pointsPerSegment(spline);
    if (count < minimum || (spline == scene::SplineKind::Bezier && count % 4 != 0))
        r.fail(countAt,
               spline == scene::SplineKind::Bezier
                   ? std::string("lathe with bezier_spline needs a multiple of 4 points")
                   : fmt::format("lathe needs at least {} points for this spline", minimum));
    std::vector<scene::ProfilePoint> points;
    for (int i = 0; i < count; ++i) {
        r.accept(Sym::Comma);
        const VectorValue v = r.parseVector();
        points.push_back({v.v[0], v.v[1]});
    }
    r.accept(Keyword::kw_sturm);  // the solver is exact enough either way
    (void)kind;
    return std::make_shared<scene::Lathe>(spline, points);
}

std::shared_ptr<const scene::Shape> parseSor(BuildContext& c, const Token& kind) {
    Reader& r = c.reader;
    const Token countAt = r.peek();
    const int count = static_cast<int>(r.parseFloat());
    if (count < 4) r.fail(countAt, "sor needs at least 4 points");
    std::vector<scene::ProfilePoint> points;
    for (int i = 0; i < count; ++i) {
        r.accept(Sym::Comma);
        const Token at = r.peek();
        const VectorValue v = r.parseVector();
        points.push_back({v.v[0], v.v[1]});
        // Only the points the curve passes through must rise; the first
        // and last only steer its slope and may sit anywhere (measured:
        // the example objects/sor1.pov repeats a height there).
        if (i >= 2 && i <= count - 2 && !(points[i].v > points[i - 1].v))
            r.fail(at, "Incorrect point in surface of revolution: heights must increase");
    }
    bool open = false;
    for (;;) {
        if (r.accept(Keyword::kw_open))
            open = true;
        else if (!r.accept(Keyword::kw_sturm))
            break;
    }
    (void)kind;
    return std::make_shared<scene::Sor>(points, open);
}

std::shared_ptr<const scene::Shape> parsePrism(BuildContext& c, const Token& kind) {
    Reader& r = c.reader;
    scene::SplineKind spline = scene::SplineKind::Linear;
    bool conic = false;
    for (;;) {
        const Token t = r.peek();
        if (acceptSplineKind(t.kw, spline)) {
            r.next();
        } else if (t.is(Keyword::kw_linear_sweep)) {
            r.next();
            conic = false;
        } else if (t.is(Keyword::kw_conic_sweep)) {
            r.next();
            conic = true;
        } else {
            break;
        }
    }
    const double h1 = r.parseFloat();
    r.accept(Sym::Comma);  // optional, as in povray
    const double h2 = r.parseFloat();
    r.accept(Sym::Comma);  // optional, as in povray
    const Token countAt = r.peek();
    const int count = static_cast<int>(r.parseFloat());
    const int minimum =
        spline == scene::SplineKind::Linear ? 3 : (spline == scene::SplineKind::Quadratic ? 4 : 5);
    if (count < minimum || (spline == scene::SplineKind::Bezier && count % 4 != 0))
        r.fail(countAt,
               spline == scene::SplineKind::Bezier
                   ? std::string("prism with bezier_spline needs a multiple of 4 points")
                   : fmt::format("prism needs at least {} points for this spline", minimum));
    std::vector<scene::ProfilePoint> points;
    for (int i = 0; i < count; ++i) {
        r.accept(Sym::Comma);
        const VectorValue v = r.parseVector();
        points.push_back({v.v[0], v.v[1]});
    }
    bool open = false;
    for (;;) {
        if (r.accept(Keyword::kw_open))
            open = true;
        else if (!r.accept(Keyword::kw_sturm))
            break;
    }
    if (h1 == h2) r.fail(kind, "prism heights must differ");
    bool unclosed = false;
    auto outline = scene::Prism::outlineOf(spline, points, unclosed);
    if (unclosed)
        r.warn(kind, "Prism not closed: its last sub-shape does not end at its first point.");
    return std::make_shared<scene::Prism>(std::move(outline), h1, h2, conic, open);
}

std::shared_ptr<const scene::Shape> parseSuperellipsoid(BuildContext& c, const Token& kind) {
    Reader& r = c.reader;
    const VectorValue v = r.parseVector();
    const double e = v.v[0], n = v.v[1];
    if (!(e > 0) || !(n > 0))
        r.fail(kind, "Illegal superellipsoid parameters: e and n must be greater than 0");
    return std::make_shared<scene::Superellipsoid>(e, n);
}

static void parseContainedBy(BuildContext& c, bool& sphere, Vec3& boxLo, Vec3& boxHi, Vec3& center,
                             double& radius) {
    Reader& r = c.reader;
    r.expect(Sym::LBrace, "'{' after 'contained_by'");
    const Token shape = r.next();
    r.expect(Sym::LBrace, "'{' after the container's kind");
    if (shape.is(Keyword::kw_box)) {
        const Vec3 a = r.parseVec3();
        r.accept(Sym::Comma);  // optional, as in povray
        const Vec3 b = r.parseVec3();
        sphere = false;
        boxLo = vmin(a, b);
        boxHi = vmax(a, b);
    } else if (shape.is(Keyword::kw_sphere)) {
        center = r.parseVec3();
        r.accept(Sym::Comma);  // optional, as in povray
        radius = std::fabs(r.parseFloat());
        sphere = true;
    } else {
        r.fail(shape,
               fmt::format("contained_by takes a box or a sphere, found {}", describeToken(shape)));
    }
    if (!r.peek().is(Sym::RBrace)) r.unsupported(r.peek(), "modifiers of a shape's container");
    r.next();
    r.expect(Sym::RBrace, "'}' closing 'contained_by'");
}

std::shared_ptr<const scene::Shape> parseIsosurface(BuildContext& c, const Token& kind) {
    Reader& r = c.reader;
    scene::IsosurfaceSettings s;
    const Token fnAt = r.peek();
    if (!r.accept(Keyword::kw_function))
        r.fail(fnAt,
               fmt::format("expected 'function' in isosurface, found {}", describeToken(fnAt)));
    s.function = r.parseXyzFunction(fnAt);

    for (;;) {
        const Token t = r.peek();
        if (t.kind != TokenKind::Word) break;
        switch (t.kw) {
            case Keyword::kw_contained_by:
                r.next();
                parseContainedBy(c, s.sphereContainer, s.boxLo, s.boxHi, s.center, s.radius);
                continue;
            case Keyword::kw_threshold:
                r.next();
                s.threshold = r.parseFloat();
                continue;
            case Keyword::kw_accuracy:
                r.next();
                s.accuracy = std::fabs(r.parseFloat());
                continue;
            case Keyword::kw_max_gradient:
                r.next();
                s.maxGradient = std::fabs(r.parseFloat());
                continue;
            case Keyword::kw_evaluate: {
                // povray adapts max_gradient per ray from these; the first
                // (the smallest gradient it assumes) is taken as the bound.
                r.next();
                const double p0 = r.parseFloat();
                r.accept(Sym::Comma);
                r.parseFloat();
                r.accept(Sym::Comma);
                r.parseFloat();
                s.maxGradient = std::fabs(p0);
                continue;
            }
            case Keyword::kw_open:
                r.next();
                s.open = true;
                continue;
            case Keyword::kw_max_trace:
                r.next();
                s.maxTrace = std::max(1, static_cast<int>(r.parseFloat()));
                continue;
            case Keyword::kw_all_intersections:
                r.next();
                s.maxTrace = 1 << 30;
                continue;
            case Keyword::kw_method:
                r.next();
                r.parseFloat();
                continue;  // povray 3.5 and later ignore it
            case Keyword::kw_precompute:
                r.unsupported(t, "isosurface precompute");
            default:
                break;
        }
        break;
    }
    if (s.accuracy <= 0) r.fail(kind, "isosurface accuracy must be greater than 0");
    if (s.maxGradient <= 0) r.fail(kind, "isosurface max_gradient must be greater than 0");
    return std::make_shared<scene::Isosurface>(std::move(s));
}

// parametric { function { X } function { Y } function { Z } <u1, v1>, <u2, v2>
// contained_by { ... } max_gradient G accuracy A precompute D, x, y, z }.
std::shared_ptr<const scene::Shape> parseParametric(BuildContext& c, const Token& kind) {
    Reader& r = c.reader;
    scene::ParametricSettings s;
    std::shared_ptr<const CompiledFunction>* slots[3] = {&s.fx, &s.fy, &s.fz};
    for (auto* slot : slots) {
        const Token fnAt = r.peek();
        if (!r.accept(Keyword::kw_function))
            r.fail(fnAt,
                   fmt::format("expected 'function' in parametric, found {}", describeToken(fnAt)));
        *slot = r.parseXyzFunction(fnAt);
        r.accept(Sym::Comma);  // povray takes a comma after each function
    }
    const VectorValue lo = r.parseVector();
    r.accept(Sym::Comma);  // optional, as in povray
    const VectorValue hi = r.parseVector();
    s.uMin = lo.v[0];
    s.vMin = lo.v[1];
    s.uMax = hi.v[0];
    s.vMax = hi.v[1];
    for (;;) {
        const Token t = r.peek();
        if (t.kind != TokenKind::Word) break;
        switch (t.kw) {
            case Keyword::kw_contained_by:
                r.next();
                parseContainedBy(c, s.sphereContainer, s.boxLo, s.boxHi, s.center, s.radius);
                continue;
            case Keyword::kw_accuracy:
                r.next();
                s.accuracy = std::fabs(r.parseFloat());
                continue;
            case Keyword::kw_max_gradient:
                r.next();
                s.maxGradient = std::fabs(r.parseFloat());
                continue;
            case Keyword::kw_precompute: {
                // A depth, then some of x, y, z: the coordinates whose
                // bounds povray tabulates for that many levels of pieces.
                r.next();
                const Token depthAt = r.peek();
                const double depth = r.parseFloat();
                if (depth < 1 || depth > 20) r.fail(depthAt, "Precompute: invalid depth (1 to 20)");
                s.precomputeDepth = static_cast<int>(depth);
                for (;;) {
                    r.accept(Sym::Comma);
                    const Token axis = r.peek();
                    const int index = axis.is(Keyword::kw_x)   ? 0
                                      : axis.is(Keyword::kw_y) ? 1
                                      : axis.is(Keyword::kw_z) ? 2
                                                               : -1;
                    if (index < 0) break;
                    r.next();
                    s.precomputeAxis[index] = true;
                }
                continue;
            }
            default:
                break;
        }
        break;
    }
    if (s.accuracy <= 0) r.fail(kind, "parametric accuracy must be greater than 0");
    if (s.maxGradient <= 0) r.fail(kind, "parametric max_gradient must be greater than 0");
    if (s.uMin > s.uMax) std::swap(s.uMin, s.uMax);
    if (s.vMin > s.vMax) std::swap(s.vMin, s.vMax);
    return std::make_shared<scene::Parametric>(std::move(s));
}

std::shared_ptr<const scene::Shape> parseSphereSweep(BuildContext& c, const Token& kind) {
    Reader& r = c.reader;
    const Token kindAt = r.peek();
    scene::SweepSpline spline;
    size_t minimum;
    if (r.accept(Keyword::kw_linear_spline)) {
        spline = scene::SweepSpline::Linear;
        minimum = 2;
    } else if (r.accept(Keyword::kw_b_spline)) {
        spline = scene::SweepSpline::BSpline;
        minimum = 4;
    } else if (r.accept(Keyword::kw_cubic_spline)) {
        spline = scene::SweepSpline::CatmullRom;
        minimum = 4;
    } else {
        r.fail(kindAt,
               fmt::format(
                   "expected linear_spline, b_spline or cubic_spline in sphere_sweep, found {}",
                   describeToken(kindAt)));
    }
    const Token countAt = r.peek();
    const double count = r.parseFloat();
    if (count < static_cast<double>(minimum))
        r.fail(countAt,
               fmt::format("sphere_sweep with {} needs at least {} spheres", kindAt.text, minimum));
    std::vector<scene::SweepPoint> points;
    for (int i = 0; i < static_cast<int>(count); ++i) {
        r.accept(Sym::Comma);
        scene::SweepPoint p;
        p.center = r.parseVec3();
        r.accept(Sym::Comma);  // optional, as in povray
        p.radius = std::fabs(r.parseFloat());
        points.push_back(p);
    }
    // povray's depth tolerance against self-shadowing; the hits here are
    // exact on the pieces, so it has nothing to do.
    if (r.accept(Keyword::kw_tolerance)) r.parseFloat();
    (void)kind;
    return std::make_shared<scene::SphereSweep>(spline, points);
}

}  // namespace frameray::sdl
