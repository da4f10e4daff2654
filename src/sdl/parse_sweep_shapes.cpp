// Shapes built from numbers swept or searched in space: superellipsoid,
// isosurface, lathe, sor, prism and sphere_sweep (seed 000 §3.4). Each
// parser starts after the shape's '{' and stops before its modifiers.
#include <fmt/format.h>

#include <cmath>
#include <unordered_set>

#include "scene/isosurface.h"
#include "scene/sphere_sweep.h"
#include "scene/superellipsoid.h"
#include "sdl/function_value.h"
#include "sdl/interpreter.h"

namespace frameray::sdl {

namespace {

// Whether `fn` or a function it calls uses a functions.inc internal or a
// kind of function the VM cannot run; returns that instruction's
// description. Rendering must not meet one (it would stop mid-frame).
std::string unavailableIn(const CompiledFunction& fn,
                          std::unordered_set<const CompiledFunction*>& seen) {
    if (!seen.insert(&fn).second) return {};
    for (const FnInstr& in : fn.code)
        if (in.op == FnOp::Internal)
            return in.a < 0
                       ? "calling a pattern, pigment, transform or spline function from a function"
                       : fmt::format("functions.inc internal function {}", in.a);
    for (const auto& callee : fn.callees) {
        std::string what = unavailableIn(*callee, seen);
        if (!what.empty()) return what;
    }
    return {};
}

}  // namespace

std::shared_ptr<const scene::Shape> Interpreter::parseSuperellipsoid(const Token& kind) {
    const VectorValue v = parseVector();
    const double e = v.v[0], n = v.v[1];
    if (!(e > 0) || !(n > 0))
        fail(kind, "Illegal superellipsoid parameters: e and n must be greater than 0");
    return std::make_shared<scene::Superellipsoid>(e, n);
}

std::shared_ptr<const scene::Shape> Interpreter::parseIsosurface(const Token& kind) {
    scene::IsosurfaceSettings s;
    const Token fnAt = peek();
    if (!accept(Keyword::kw_function))
        fail(fnAt, fmt::format("expected 'function' in isosurface, found {}", describeToken(fnAt)));
    const Value body = parseFunctionBody({"x", "y", "z"});
    const FunctionValue& fn = *std::get<FunctionPtr>(body);
    if (!fn.unsupported.empty()) unsupported(fnAt, fn.unsupported);
    std::unordered_set<const CompiledFunction*> seen;
    if (const std::string what = unavailableIn(*fn.compiled, seen); !what.empty())
        unsupported(fnAt, what);
    s.function = fn.compiled;

    for (;;) {
        const Token t = peek();
        if (t.kind != TokenKind::Word) break;
        switch (t.kw) {
            case Keyword::kw_contained_by: {
                next();
                expect(Sym::LBrace, "'{' after 'contained_by'");
                const Token shape = next();
                expect(Sym::LBrace, "'{' after the container's kind");
                if (shape.is(Keyword::kw_box)) {
                    const Vec3 a = parseVec3();
                    expect(Sym::Comma, "',' between the corners");
                    const Vec3 b = parseVec3();
                    s.sphereContainer = false;
                    s.boxLo = vmin(a, b);
                    s.boxHi = vmax(a, b);
                } else if (shape.is(Keyword::kw_sphere)) {
                    s.center = parseVec3();
                    expect(Sym::Comma, "',' between the centre and the radius");
                    s.radius = std::fabs(parseFloat());
                    s.sphereContainer = true;
                } else {
                    fail(shape, fmt::format("contained_by takes a box or a sphere, found {}",
                                            describeToken(shape)));
                }
                if (!peek().is(Sym::RBrace))
                    unsupported(peek(), "modifiers of an isosurface's container");
                next();
                expect(Sym::RBrace, "'}' closing 'contained_by'");
                continue;
            }
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
        expect(Sym::Comma, "',' between a sphere's centre and its radius");
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
