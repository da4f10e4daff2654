#include "scene/polynomial_bounds.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "util/roots.h"

namespace frameray::scene {

namespace {

struct Interval {
    double lo, hi;
};

Interval times(const Interval& a, const Interval& b) {
    const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    return {*std::min_element(p, p + 4), *std::max_element(p, p + 4)};
}

// [lo, hi]^n for n = 0 .. maxPower.
using PowerTable = std::array<Interval, kMaxPolynomialDegree + 1>;

void powers(double lo, double hi, int maxPower, PowerTable& out) {
    out[0] = {1, 1};
    double pl = 1, ph = 1;
    for (int n = 1; n <= maxPower; ++n) {
        pl *= lo;
        ph *= hi;
        if (n % 2 == 1 || lo >= 0)
            out[n] = {pl, ph};
        else if (hi <= 0)
            out[n] = {ph, pl};
        else
            out[n] = {0, std::max(pl, ph)};
    }
}

double binomialMultinomial(int n, int a, int b) {
    // n! / (a! b! (n-a-b)!)
    double r = 1;
    for (int k = 1; k <= n; ++k) r *= k;
    for (int k = 1; k <= a; ++k) r /= k;
    for (int k = 1; k <= b; ++k) r /= k;
    for (int k = 1; k <= n - a - b; ++k) r /= k;
    return r;
}

// A lower bound m > 0 of (the degree-`degree` part of the
// polynomial) on the unit sphere, or 0 when none is proved. Both proofs
// need every top-degree monomial to have even powers only.
double leadingLowerBound(const std::vector<PolynomialTerm>& terms, int degree) {
    if (degree < 2 || degree % 2 != 0) return 0;
    const int half = degree / 2;
    // coefficient of x^2a y^2b z^2c, indexed [a][b].
    std::array<std::array<double, kMaxPolynomialDegree + 1>, kMaxPolynomialDegree + 1> c{};
    for (const PolynomialTerm& t : terms) {
        if (t.i + t.j + t.k != degree) continue;
        const double v = t.coefficient;
        if (t.i % 2 || t.j % 2 || t.k % 2 || v < 0) return 0;
        c[t.i / 2][t.j / 2] += v;
    }
    // (1) the pure powers alone: x^n + y^n + z^n >= 3 (|p|^2 / 3)^(n/2).
    const double pure = std::min({c[half][0], c[0][half], c[0][0]});
    double m = pure > 0 ? pure * std::pow(3.0, 1 - half) : 0;
    // (2) every monomial of (x^2 + y^2 + z^2)^half present: the form is at
    // least min(C / multinomial) * |p|^degree.
    double ratio = kInfinity;
    for (int a = 0; a <= half; ++a)
        for (int b = 0; a + b <= half; ++b)
            ratio = std::min(ratio, c[a][b] / binomialMultinomial(half, a, b));
    if (std::isfinite(ratio)) m = std::max(m, ratio);
    return m;
}

// The radius beyond which m r^degree exceeds every lower-degree term's
// largest possible magnitude sum_d lower[d] r^d (one sign change in the
// coefficients of m r^n - sum lower[d] r^d: a single positive root).
double escapeRadius(double m, int degree,
                    const std::array<double, kMaxPolynomialDegree + 1>& lower) {
    auto g = [&](double r) {
        double v = m * std::pow(r, degree);
        for (int d = 0; d < degree; ++d) v -= lower[d] * std::pow(r, d);
        return v;
    };
    double hi = 1;
    for (int n = 0; g(hi) <= 0; ++n) {
        if (n > 2000) return kInfinity;
        hi *= 2;
    }
    double lo = 0;
    for (int n = 0; n < 100 && hi - lo > hi * 1e-12; ++n) {
        const double mid = 0.5 * (lo + hi);
        (g(mid) > 0 ? hi : lo) = mid;
    }
    return hi * (1 + 1e-9) + 1e-300;
}

struct Cell {
    Vec3 lo, hi;
};

// Whether P may be <= 0 somewhere in the cell (interval arithmetic,
// with a tolerance for its rounding).
bool mayReachZero(const std::vector<PolynomialTerm>& terms, int degree, const Cell& cell) {
    PowerTable px, py, pz;
    powers(cell.lo.x, cell.hi.x, degree, px);
    powers(cell.lo.y, cell.hi.y, degree, py);
    powers(cell.lo.z, cell.hi.z, degree, pz);
    double low = 0, magnitude = 0;
    for (const PolynomialTerm& t : terms) {
        const Interval m = times(times(px[t.i], py[t.j]), pz[t.k]);
        const double a = t.coefficient;
        low += a >= 0 ? a * m.lo : a * m.hi;
        magnitude += std::fabs(a) * std::max(std::fabs(m.lo), std::fabs(m.hi));
    }
    return low <= 1e-9 * magnitude;
}

void split(const Cell& c, std::array<Cell, 8>& out) {
    const Vec3 mid = (c.lo + c.hi) * 0.5;
    for (int octant = 0; octant < 8; ++octant) {
        out[octant].lo = Vec3(octant & 1 ? mid.x : c.lo.x, octant & 2 ? mid.y : c.lo.y,
                              octant & 4 ? mid.z : c.lo.z);
        out[octant].hi = Vec3(octant & 1 ? c.hi.x : mid.x, octant & 2 ? c.hi.y : mid.y,
                              octant & 4 ? c.hi.z : mid.z);
    }
}

// How far the region where P may be <= 0 reaches along +axis (side 1) or
// -axis (side -1), as side * coordinate: best-first branch and bound over
// octree cells, always splitting the live cell that reaches furthest,
// until that cell is smaller than `resolution` (or the work budget runs
// out: then the furthest live cell answers, still conservative). -inf
// when no cell can reach zero.
double reach(const std::vector<PolynomialTerm>& terms, int degree, const Cell& start, int axis,
             double side, double resolution) {
    constexpr int kMaxSplits = 1500;
    auto extent = [&](const Cell& c) { return side > 0 ? c.hi[axis] : -c.lo[axis]; };
    auto further = [&](const Cell& a, const Cell& b) { return extent(a) < extent(b); };
    std::vector<Cell> heap{start};
    std::array<Cell, 8> children;
    for (int splits = 0; !heap.empty(); ++splits) {
        std::pop_heap(heap.begin(), heap.end(), further);
        const Cell c = heap.back();
        heap.pop_back();
        const Vec3 size = c.hi - c.lo;
        if (std::max({size.x, size.y, size.z}) <= resolution || splits >= kMaxSplits)
            return extent(c);
        split(c, children);
        for (const Cell& child : children)
            if (mayReachZero(terms, degree, child)) {
                heap.push_back(child);
                std::push_heap(heap.begin(), heap.end(), further);
            }
    }
    return -kInfinity;
}

Bounds searchCells(const std::vector<PolynomialTerm>& terms, int degree, double radius) {
    const Cell ball{Vec3(-radius, -radius, -radius), Vec3(radius, radius, radius)};
    if (!mayReachZero(terms, degree, ball)) return {};
    const double resolution = radius / 64;
    Bounds box;
    for (int axis = 0; axis < 3; ++axis) {
        box.hi[axis] = reach(terms, degree, ball, axis, 1, resolution);
        box.lo[axis] = -reach(terms, degree, ball, axis, -1, resolution);
    }
    if (box.isEmpty()) return {};
    const double margin = radius * 1e-9;
    box.lo -= Vec3(margin, margin, margin);
    box.hi += Vec3(margin, margin, margin);
    return box.padded();
}

}  // namespace

PolynomialBounds polynomialBounds(const std::vector<PolynomialTerm>& terms) {
    PolynomialBounds out;
    int degree = 0;
    for (const PolynomialTerm& t : terms) degree = std::max(degree, t.i + t.j + t.k);
    if (degree < 2 || degree > kMaxPolynomialDegree) return out;
    std::array<double, kMaxPolynomialDegree + 1> lower{};
    for (const PolynomialTerm& t : terms)
        if (t.i + t.j + t.k < degree) lower[t.i + t.j + t.k] += std::fabs(t.coefficient);
    // Only a polynomial positive far away is bounded: one negative far away
    // has an unbounded inside, which the CSG bounds logic would have to
    // treat as reaching past the surface box (left unbounded, as povray).
    const double m = leadingLowerBound(terms, degree);
    if (!(m > 0)) return out;
    const double radius = escapeRadius(m, degree, lower);
    if (!std::isfinite(radius)) return out;
    out.surface = searchCells(terms, degree, radius);
    out.inside = out.surface;
    return out;
}

}  // namespace frameray::scene
