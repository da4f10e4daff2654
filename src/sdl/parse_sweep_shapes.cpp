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
#include "sdl/function_value.h"
#include "sdl/interpreter.h"

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

std::shared_ptr<const scene::Shape> Interpreter::parseLathe(const Token& kind) {
    scene::SplineKind spline = scene::SplineKind::Linear;
    if (acceptSplineKind(peek().kw, spline)) next();
    const Token countAt = peek();
    const int count = static_cast<int>(parseFloat());
    const int minimum = scene::pointsPerSegment(spline);
    if (count < minimum || (spline == scene::SplineKind::Bezier && count % 4 != 0))
        fail(countAt, spline == scene::SplineKind::Bezier
                          ? std::string("lathe with bezier_spline needs a multiple of 4 points")
                          : fmt::format("lathe needs at least {} points for this spline", minimum));
    std::vector<scene::ProfilePoint> points;
    for (int i = 0; i < count; ++i) {
        accept(Sym::Comma);
        const VectorValue v = parseVector();
        points.push_back({v.v[0], v.v[1]});
    }
    accept(Keyword::kw_sturm);  // the solver is exact enough either way
    (void)kind;
    return std::make_shared<scene::Lathe>(spline, points);
}

std::shared_ptr<const scene::Shape> Interpreter::parseSor(const Token& kind) {
    const Token countAt = peek();
    const int count = static_cast<int>(parseFloat());
    if (count < 4) fail(countAt, "sor needs at least 4 points");
    std::vector<scene::ProfilePoint> points;
    for (int i = 0; i < count; ++i) {
        accept(Sym::Comma);
        const Token at = peek();
        const VectorValue v = parseVector();
        points.push_back({v.v[0], v.v[1]});
        // Only the points the curve passes through must rise; the first
        // and last only steer its slope and may sit anywhere (measured:
        // the example objects/sor1.pov repeats a height there).
        if (i >= 2 && i <= count - 2 && !(points[i].v > points[i - 1].v))
            fail(at, "Incorrect point in surface of revolution: heights must increase");
    }
    bool open = false;
    for (;;) {
        if (accept(Keyword::kw_open))
            open = true;
        else if (!accept(Keyword::kw_sturm))
            break;
    }
    (void)kind;
    return std::make_shared<scene::Sor>(points, open);
}

std::shared_ptr<const scene::Shape> Interpreter::parsePrism(const Token& kind) {
    scene::SplineKind spline = scene::SplineKind::Linear;
    bool conic = false;
    for (;;) {
        const Token t = peek();
        if (acceptSplineKind(t.kw, spline)) {
            next();
        } else if (t.is(Keyword::kw_linear_sweep)) {
            next();
            conic = false;
        } else if (t.is(Keyword::kw_conic_sweep)) {
            next();
            conic = true;
        } else {
            break;
        }
    }
    const double h1 = parseFloat();
    accept(Sym::Comma);  // optional, as in povray
    const double h2 = parseFloat();
    accept(Sym::Comma);  // optional, as in povray
    const Token countAt = peek();
    const int count = static_cast<int>(parseFloat());
    const int minimum =
        spline == scene::SplineKind::Linear ? 3 : (spline == scene::SplineKind::Quadratic ? 4 : 5);
    if (count < minimum || (spline == scene::SplineKind::Bezier && count % 4 != 0))
        fail(countAt, spline == scene::SplineKind::Bezier
                          ? std::string("prism with bezier_spline needs a multiple of 4 points")
                          : fmt::format("prism needs at least {} points for this spline", minimum));
    std::vector<scene::ProfilePoint> points;
    for (int i = 0; i < count; ++i) {
        accept(Sym::Comma);
        const VectorValue v = parseVector();
        points.push_back({v.v[0], v.v[1]});
    }
    bool open = false;
    for (;;) {
        if (accept(Keyword::kw_open))
            open = true;
        else if (!accept(Keyword::kw_sturm))
            break;
    }
    if (h1 == h2) fail(kind, "prism heights must differ");
    bool unclosed = false;
    auto outline = scene::Prism::outlineOf(spline, points, unclosed);
    if (unclosed)
        warn(kind, "Prism not closed: its last sub-shape does not end at its first point.");
    return std::make_shared<scene::Prism>(std::move(outline), h1, h2, conic, open);
}

std::shared_ptr<const scene::Shape> Interpreter::parseSuperellipsoid(const Token& kind) {
    const VectorValue v = parseVector();
    const double e = v.v[0], n = v.v[1];
    if (!(e > 0) || !(n > 0))
        fail(kind, "Illegal superellipsoid parameters: e and n must be greater than 0");
    return std::make_shared<scene::Superellipsoid>(e, n);
}

void Interpreter::parseContainedBy(bool& sphere, Vec3& boxLo, Vec3& boxHi, Vec3& center,
                                   double& radius) {
    expect(Sym::LBrace, "'{' after 'contained_by'");
    const Token shape = next();
    expect(Sym::LBrace, "'{' after the container's kind");
    if (shape.is(Keyword::kw_box)) {
        const Vec3 a = parseVec3();
        accept(Sym::Comma);  // optional, as in povray
        const Vec3 b = parseVec3();
        sphere = false;
        boxLo = vmin(a, b);
        boxHi = vmax(a, b);
    } else if (shape.is(Keyword::kw_sphere)) {
        center = parseVec3();
        accept(Sym::Comma);  // optional, as in povray
        radius = std::fabs(parseFloat());
        sphere = true;
    } else {
        fail(shape,
             fmt::format("contained_by takes a box or a sphere, found {}", describeToken(shape)));
    }
    if (!peek().is(Sym::RBrace)) unsupported(peek(), "modifiers of a shape's container");
    next();
    expect(Sym::RBrace, "'}' closing 'contained_by'");
}

std::shared_ptr<const scene::Shape> Interpreter::parseIsosurface(const Token& kind) {
    scene::IsosurfaceSettings s;
    const Token fnAt = peek();
    if (!accept(Keyword::kw_function))
        fail(fnAt, fmt::format("expected 'function' in isosurface, found {}", describeToken(fnAt)));
    s.function = parseXyzFunction(fnAt);

    for (;;) {
        const Token t = peek();
        if (t.kind != TokenKind::Word) break;
        switch (t.kw) {
            case Keyword::kw_contained_by:
                next();
                parseContainedBy(s.sphereContainer, s.boxLo, s.boxHi, s.center, s.radius);
                continue;
            case Keyword::kw_threshold:
                next();
                s.threshold = parseFloat();
                continue;
            case Keyword::kw_accuracy:
                next();
                s.accuracy = std::fabs(parseFloat());
                continue;
            case Keyword::kw_max_gradient:
                next();
                s.maxGradient = std::fabs(parseFloat());
                continue;
            case Keyword::kw_evaluate: {
                // povray adapts max_gradient per ray from these; the first
                // (the smallest gradient it assumes) is taken as the bound.
                next();
                const double p0 = parseFloat();
                accept(Sym::Comma);
                parseFloat();
                accept(Sym::Comma);
                parseFloat();
                s.maxGradient = std::fabs(p0);
                continue;
            }
            case Keyword::kw_open:
                next();
                s.open = true;
                continue;
            case Keyword::kw_max_trace:
                next();
                s.maxTrace = std::max(1, static_cast<int>(parseFloat()));
                continue;
            case Keyword::kw_all_intersections:
                next();
                s.maxTrace = 1 << 30;
                continue;
            case Keyword::kw_method:
                next();
                parseFloat();
                continue;  // povray 3.5 and later ignore it
            case Keyword::kw_precompute:
                unsupported(t, "isosurface precompute");
            default:
                break;
        }
        break;
    }
    if (s.accuracy <= 0) fail(kind, "isosurface accuracy must be greater than 0");
    if (s.maxGradient <= 0) fail(kind, "isosurface max_gradient must be greater than 0");
    return std::make_shared<scene::Isosurface>(std::move(s));
}

// parametric { function { X } function { Y } function { Z } <u1, v1>, <u2, v2>
// contained_by { ... } max_gradient G accuracy A precompute D, x, y, z }.
std::shared_ptr<const scene::Shape> Interpreter::parseParametric(const Token& kind) {
    scene::ParametricSettings s;
    std::shared_ptr<const CompiledFunction>* slots[3] = {&s.fx, &s.fy, &s.fz};
    for (auto* slot : slots) {
        const Token fnAt = peek();
        if (!accept(Keyword::kw_function))
            fail(fnAt,
                 fmt::format("expected 'function' in parametric, found {}", describeToken(fnAt)));
        *slot = parseXyzFunction(fnAt);
        accept(Sym::Comma);  // povray takes a comma after each function
    }
    const VectorValue lo = parseVector();
    accept(Sym::Comma);  // optional, as in povray
    const VectorValue hi = parseVector();
    s.uMin = lo.v[0];
    s.vMin = lo.v[1];
    s.uMax = hi.v[0];
    s.vMax = hi.v[1];
    for (;;) {
        const Token t = peek();
        if (t.kind != TokenKind::Word) break;
        switch (t.kw) {
            case Keyword::kw_contained_by:
                next();
                parseContainedBy(s.sphereContainer, s.boxLo, s.boxHi, s.center, s.radius);
                continue;
            case Keyword::kw_accuracy:
                next();
                s.accuracy = std::fabs(parseFloat());
                continue;
            case Keyword::kw_max_gradient:
                next();
                s.maxGradient = std::fabs(parseFloat());
                continue;
            case Keyword::kw_precompute: {
                // povray tabulates the first levels of its subdivision to
                // go faster; the surface is the same, so only the syntax
                // is checked: a depth, then some of x, y, z.
                next();
                const Token depthAt = peek();
                const double depth = parseFloat();
                if (depth < 1 || depth > 20) fail(depthAt, "Precompute: invalid depth (1 to 20)");
                for (;;) {
                    accept(Sym::Comma);
                    const Token axis = peek();
                    if (axis.is(Keyword::kw_x) || axis.is(Keyword::kw_y) || axis.is(Keyword::kw_z))
                        next();
                    else
                        break;
                }
                continue;
            }
            default:
                break;
        }
        break;
    }
    if (s.accuracy <= 0) fail(kind, "parametric accuracy must be greater than 0");
    if (s.maxGradient <= 0) fail(kind, "parametric max_gradient must be greater than 0");
    if (s.uMin > s.uMax) std::swap(s.uMin, s.uMax);
    if (s.vMin > s.vMax) std::swap(s.vMin, s.vMax);
    return std::make_shared<scene::Parametric>(std::move(s));
}

std::shared_ptr<const scene::Shape> Interpreter::parseSphereSweep(const Token& kind) {
    const Token kindAt = peek();
    scene::SweepSpline spline;
    size_t minimum;
    if (accept(Keyword::kw_linear_spline)) {
        spline = scene::SweepSpline::Linear;
        minimum = 2;
    } else if (accept(Keyword::kw_b_spline)) {
        spline = scene::SweepSpline::BSpline;
        minimum = 4;
    } else if (accept(Keyword::kw_cubic_spline)) {
        spline = scene::SweepSpline::CatmullRom;
        minimum = 4;
    } else {
        fail(kindAt,
             fmt::format(
                 "expected linear_spline, b_spline or cubic_spline in sphere_sweep, found {}",
                 describeToken(kindAt)));
    }
    const Token countAt = peek();
    const double count = parseFloat();
    if (count < static_cast<double>(minimum))
        fail(countAt,
             fmt::format("sphere_sweep with {} needs at least {} spheres", kindAt.text, minimum));
    std::vector<scene::SweepPoint> points;
    for (int i = 0; i < static_cast<int>(count); ++i) {
        accept(Sym::Comma);
        scene::SweepPoint p;
        p.center = parseVec3();
        accept(Sym::Comma);  // optional, as in povray
        p.radius = std::fabs(parseFloat());
        points.push_back(p);
    }
    // povray's depth tolerance against self-shadowing; the hits here are
    // exact on the pieces, so it has nothing to do.
    if (accept(Keyword::kw_tolerance)) parseFloat();
    (void)kind;
    return std::make_shared<scene::SphereSweep>(spline, points);
}

}  // namespace frameray::sdl
