// Splines: `spline { [type] t1, <p1>, t2, <p2> ... }` and calls S(t) or
// S(t, type). The interpolation rules were read off povray 3.7's output:
//   linear     piecewise linear;
//   quadratic  on [t_i, t_i+1] the parabola through points i-1, i, i+1
//              (points 0, 1, 2 on the first segment);
//   cubic      Hermite segments whose tangent at a point is the mean of the
//              two neighbouring secant slopes; the first and last points
//              only steer, the curve runs from the second to the next-to-
//              last point;
//   natural    the natural cubic spline (zero curvature at both ends).
// Outside its range a spline keeps the value at the nearest end.
#include <fmt/format.h>

#include <algorithm>

#include "sdl/reader.h"

namespace frameray::sdl {

enum class SplineType { Linear, Quadratic, Cubic, Natural };

struct SplineValue {
    SplineType type = SplineType::Linear;
    std::vector<double> t;
    std::vector<VectorValue> p;
    uint8_t size = 2;
};

namespace {

bool splineTypeKeyword(Keyword kw, SplineType& out) {
    switch (kw) {
        case Keyword::kw_linear_spline:
            out = SplineType::Linear;
            return true;
        case Keyword::kw_quadratic_spline:
            out = SplineType::Quadratic;
            return true;
        case Keyword::kw_cubic_spline:
            out = SplineType::Cubic;
            return true;
        case Keyword::kw_natural_spline:
            out = SplineType::Natural;
            return true;
        default:
            return false;
    }
}

using Vec5 = std::array<double, 5>;

Vec5 lerp(const Vec5& a, const Vec5& b, double s) {
    Vec5 r;
    for (int k = 0; k < 5; ++k) r[k] = a[k] + (b[k] - a[k]) * s;
    return r;
}

// Index i of the segment [t_i, t_i+1] holding t, within [first, last].
size_t segmentOf(const std::vector<double>& t, double x, size_t first, size_t last) {
    size_t i = first;
    while (i + 1 < last && x >= t[i + 1]) ++i;
    return i;
}

Vec5 evalLinear(const SplineValue& s, double x) {
    const size_t n = s.t.size();
    if (x <= s.t.front()) return s.p.front().v;
    if (x >= s.t.back()) return s.p.back().v;
    const size_t i = segmentOf(s.t, x, 0, n - 1);
    return lerp(s.p[i].v, s.p[i + 1].v, (x - s.t[i]) / (s.t[i + 1] - s.t[i]));
}

Vec5 evalQuadratic(const SplineValue& s, double x) {
    const size_t n = s.t.size();
    if (x <= s.t.front()) return s.p.front().v;
    if (x >= s.t.back()) return s.p.back().v;
    const size_t seg = segmentOf(s.t, x, 0, n - 1);
    const size_t a = seg == 0 ? 0 : seg - 1;  // Lagrange through a, a+1, a+2
    const double t0 = s.t[a], t1 = s.t[a + 1], t2 = s.t[a + 2];
    const double l0 = (x - t1) * (x - t2) / ((t0 - t1) * (t0 - t2));
    const double l1 = (x - t0) * (x - t2) / ((t1 - t0) * (t1 - t2));
    const double l2 = (x - t0) * (x - t1) / ((t2 - t0) * (t2 - t1));
    Vec5 r;
    for (int k = 0; k < 5; ++k)
        r[k] = l0 * s.p[a].v[k] + l1 * s.p[a + 1].v[k] + l2 * s.p[a + 2].v[k];
    return r;
}

Vec5 evalCubic(const SplineValue& s, double x) {
    const size_t n = s.t.size();
    if (n == 3) return s.p[1].v;
    const size_t first = 1, last = n - 2;
    if (x <= s.t[first]) return s.p[first].v;
    if (x >= s.t[last]) return s.p[last].v;
    const size_t i = segmentOf(s.t, x, first, last);
    const double h = s.t[i + 1] - s.t[i];
    const double u = (x - s.t[i]) / h;
    const double h00 = 2 * u * u * u - 3 * u * u + 1, h10 = u * u * u - 2 * u * u + u;
    const double h01 = -2 * u * u * u + 3 * u * u, h11 = u * u * u - u * u;
    auto tangent = [&](size_t j, int k) {
        const double before = (s.p[j].v[k] - s.p[j - 1].v[k]) / (s.t[j] - s.t[j - 1]);
        const double after = (s.p[j + 1].v[k] - s.p[j].v[k]) / (s.t[j + 1] - s.t[j]);
        return 0.5 * (before + after);
    };
    Vec5 r;
    for (int k = 0; k < 5; ++k)
        r[k] = h00 * s.p[i].v[k] + h10 * h * tangent(i, k) + h01 * s.p[i + 1].v[k] +
               h11 * h * tangent(i + 1, k);
    return r;
}

Vec5 evalNatural(const SplineValue& s, double x) {
    const size_t n = s.t.size();
    if (x <= s.t.front()) return s.p.front().v;
    if (x >= s.t.back()) return s.p.back().v;
    // Second derivatives from the tridiagonal system (Thomas algorithm),
    // zero at both ends; per component.
    std::vector<double> h(n - 1);
    for (size_t i = 0; i + 1 < n; ++i) h[i] = s.t[i + 1] - s.t[i];
    const size_t seg = segmentOf(s.t, x, 0, n - 1);
    const double a = (s.t[seg + 1] - x) / h[seg], b = (x - s.t[seg]) / h[seg];
    Vec5 r{};
    for (int k = 0; k < 5; ++k) {
        std::vector<double> m(n, 0.0), c(n, 0.0), d(n, 0.0);
        for (size_t i = 1; i + 1 < n; ++i) {
            const double rhs = 6 * ((s.p[i + 1].v[k] - s.p[i].v[k]) / h[i] -
                                    (s.p[i].v[k] - s.p[i - 1].v[k]) / h[i - 1]);
            const double diag = 2 * (h[i - 1] + h[i]) - h[i - 1] * c[i - 1];
            c[i] = h[i] / diag;
            d[i] = (rhs - h[i - 1] * d[i - 1]) / diag;
        }
        for (size_t i = n - 2; i >= 1; --i) m[i] = d[i] - c[i] * m[i + 1];
        r[k] = a * s.p[seg].v[k] + b * s.p[seg + 1].v[k] +
               ((a * a * a - a) * m[seg] + (b * b * b - b) * m[seg + 1]) * h[seg] * h[seg] / 6;
    }
    return r;
}

}  // namespace

namespace {

VectorValue evaluateSpline(const SplineValue& spline, double x, SplineType type) {
    VectorValue out;
    out.size = spline.size;
    const size_t n = spline.t.size();
    if (n == 1) {
        out.v = spline.p[0].v;
    } else if (type == SplineType::Cubic && n >= 3) {
        out.v = evalCubic(spline, x);
    } else if (type == SplineType::Quadratic && n >= 3) {
        out.v = evalQuadratic(spline, x);
    } else if (type == SplineType::Natural && n >= 3) {
        out.v = evalNatural(spline, x);
    } else {
        out.v = evalLinear(spline, x);
    }
    return out;
}

}  // namespace

Value Reader::parseSpline() {
    next();  // spline
    expect(Sym::LBrace, "'{' after 'spline'");
    auto spline = std::make_shared<SplineValue>();
    if (peek().isIdentifier()) {
        const Token id = next();
        const Value v = identifierValue(id);
        const auto* sp = std::get_if<SplinePtr>(&v);
        if (!sp) fail(id, fmt::format("'{}' is a {}, not a spline", id.text, valueKindName(v)));
        *spline = **sp;
    }
    SplineType type;
    if (splineTypeKeyword(peek().kw, type)) {
        next();
        spline->type = type;
    }
    while (!accept(Sym::RBrace)) {
        const Token at = peek();
        const double t = parseFloat();
        accept(Sym::Comma);  // optional, as in povray
        const Token pointAt = peek();
        const Value v = parseExpression();
        if (!std::holds_alternative<VectorValue>(v))
            fail(pointAt,
                 fmt::format("a spline point must be a vector of 2 to 5 components, not a {}",
                             valueKindName(v)));
        const VectorValue point = std::get<VectorValue>(v);
        accept(Sym::Comma);
        // Entries are kept sorted; a repeated parameter keeps its first
        // point (povray 3.7's behaviour).
        const auto pos = std::lower_bound(spline->t.begin(), spline->t.end(), t);
        const size_t i = static_cast<size_t>(pos - spline->t.begin());
        if (pos == spline->t.end() || *pos != t) {
            spline->t.insert(pos, t);
            spline->p.insert(spline->p.begin() + static_cast<long>(i), point);
        }
        spline->size = std::max(spline->size, point.isColor ? uint8_t(5) : point.size);
        (void)at;
    }
    if (spline->t.empty()) fail(peek(), "a spline needs at least one point");
    return SplinePtr(spline);
}

Value Reader::callSpline(const SplineValue& spline, const Token& at) {
    expect(Sym::LParen, "'('");
    const double x = parseFloat();
    SplineType type = spline.type;
    if (accept(Sym::Comma)) {
        const Token kw = next();
        if (!splineTypeKeyword(kw.kw, type))
            fail(kw, fmt::format("expected a spline type, found {}", describeToken(kw)));
    }
    expect(Sym::RParen, "')'");
    (void)at;
    return evaluateSpline(spline, x, type);
}

VectorValue splineAt(const SplineValue& s, double x) {
    return evaluateSpline(s, x, s.type);
}

}  // namespace frameray::sdl
