#include "scene/quadric.h"

#include <algorithm>
#include <cmath>

#include "scene/shape_math.h"

namespace frameray::scene {

double Quadric::value(const Vec3& p) const {
    const auto& k = k_;
    return p.x * (k.a * p.x + k.d * p.y + k.e * p.z + k.g) + p.y * (k.b * p.y + k.f * p.z + k.h) +
           p.z * (k.c * p.z + k.i) + k.j;
}

void Quadric::allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const {
    const auto& k = k_;
    const Vec3& o = ray.origin;
    const Vec3& d = ray.direction;
    // f(o + t d) = a t² + b t + c.
    const double a = k.a * d.x * d.x + k.b * d.y * d.y + k.c * d.z * d.z + k.d * d.x * d.y +
                     k.e * d.x * d.z + k.f * d.y * d.z;
    const double b = 2 * (k.a * o.x * d.x + k.b * o.y * d.y + k.c * o.z * d.z) +
                     k.d * (o.x * d.y + o.y * d.x) + k.e * (o.x * d.z + o.z * d.x) +
                     k.f * (o.y * d.z + o.z * d.y) + k.g * d.x + k.h * d.y + k.i * d.z;
    const double c = value(o);
    double t0, t1;
    const int n = detail::solveQuadratic(a, b, c, t0, t1);
    if (n >= 1) detail::keepIfInRange(t0, tMin, tMax, ts);
    if (n == 2 && t1 != t0) detail::keepIfInRange(t1, tMin, tMax, ts);
}

Vec3 Quadric::normal(const Vec3& p) const {
    const auto& k = k_;
    return normalize({2 * k.a * p.x + k.d * p.y + k.e * p.z + k.g,
                      2 * k.b * p.y + k.d * p.x + k.f * p.z + k.h,
                      2 * k.c * p.z + k.e * p.x + k.f * p.y + k.i});
}

bool Quadric::ellipsoidBounds(Bounds& box, bool& interiorNegative) const {
    // f(p) = p'Qp + l.p + J with Q symmetric; definite Q makes the surface
    // an ellipsoid (p-c)'Q(p-c) = m around c = -Q^-1 l / 2.
    const auto& k = k_;
    double q[3][3] = {{k.a, k.d / 2, k.e / 2}, {k.d / 2, k.b, k.f / 2}, {k.e / 2, k.f / 2, k.c}};
    const double sign = q[0][0] < 0 ? -1.0 : 1.0;  // work with the positive definite one of Q, -Q
    for (auto& row : q)
        for (double& v : row) v *= sign;
    const double m2 = q[0][0] * q[1][1] - q[0][1] * q[1][0];
    const double det = q[0][0] * (q[1][1] * q[2][2] - q[1][2] * q[2][1]) -
                       q[0][1] * (q[1][0] * q[2][2] - q[1][2] * q[2][0]) +
                       q[0][2] * (q[1][0] * q[2][1] - q[1][1] * q[2][0]);
    if (!(q[0][0] > 0 && m2 > 0 && det > 0)) return false;
    // Q^-1 by cofactors (Q symmetric).
    double inv[3][3];
    inv[0][0] = (q[1][1] * q[2][2] - q[1][2] * q[2][1]) / det;
    inv[0][1] = (q[0][2] * q[2][1] - q[0][1] * q[2][2]) / det;
    inv[0][2] = (q[0][1] * q[1][2] - q[0][2] * q[1][1]) / det;
    inv[1][1] = (q[0][0] * q[2][2] - q[0][2] * q[2][0]) / det;
    inv[1][2] = (q[0][2] * q[1][0] - q[0][0] * q[1][2]) / det;
    inv[2][2] = (q[0][0] * q[1][1] - q[0][1] * q[1][0]) / det;
    inv[1][0] = inv[0][1];
    inv[2][0] = inv[0][2];
    inv[2][1] = inv[1][2];
    const double l[3] = {sign * k.g, sign * k.h, sign * k.i};
    Vec3 c;
    for (int r = 0; r < 3; ++r)
        c[r] = -0.5 * (inv[r][0] * l[0] + inv[r][1] * l[1] + inv[r][2] * l[2]);
    // m = c'Qc - J (with J's sign matched to Q's).
    double cqc = 0;
    for (int r = 0; r < 3; ++r)
        for (int s = 0; s < 3; ++s) cqc += c[r] * q[r][s] * c[s];
    const double m = cqc - sign * k.j;
    interiorNegative = sign > 0;
    if (m < 0) {
        box = {};  // no real points
        return true;
    }
    const Vec3 half{std::sqrt(m * inv[0][0]), std::sqrt(m * inv[1][1]), std::sqrt(m * inv[2][2])};
    box = {c - half, c + half};
    return true;
}

namespace {

// The least of a x^2 + g x over [lo, hi] (ends may be infinite); -infinity
// when it has none.
double leastOver(double a, double g, double lo, double hi) {
    auto f = [&](double x) { return a * x * x + g * x; };
    if (a == 0) {
        if (g == 0) return 0;
        const double end = g > 0 ? lo : hi;
        return std::isinf(end) ? -kInfinity : f(end);
    }
    if (a < 0) return std::isinf(lo) || std::isinf(hi) ? -kInfinity : std::min(f(lo), f(hi));
    const double vertex = std::clamp(-g / (2 * a), lo, hi);
    return f(vertex);
}

}  // namespace

Bounds Quadric::insideBoundsWithin(const Bounds& box) const {
    const auto& k = k_;
    Bounds out = insideBounds().intersected(box);
    if (out.isEmpty() || k.d != 0 || k.e != 0 || k.f != 0) return out;
    // f = sum_i (a_i x_i^2 + g_i x_i) + j <= 0 separates by axis: along
    // axis i, a_i x^2 + g_i x <= -j - (the least the other axes can add).
    const double a[3] = {k.a, k.b, k.c}, g[3] = {k.g, k.h, k.i};
    for (int pass = 0; pass < 2; ++pass)
        for (int i = 0; i < 3; ++i) {
            double rest = k.j;
            for (int o = 0; o < 3; ++o)
                if (o != i) rest += leastOver(a[o], g[o], out.lo[o], out.hi[o]);
            if (std::isinf(rest) || std::isnan(rest)) continue;  // no limit along i
            const double r = -rest;
            double lo = -kInfinity, hi = kInfinity;
            if (a[i] > 0) {
                const double disc = g[i] * g[i] + 4 * a[i] * r;
                if (disc < 0) return {};
                const double root = std::sqrt(disc);
                lo = (-g[i] - root) / (2 * a[i]);
                hi = (-g[i] + root) / (2 * a[i]);
            } else if (a[i] == 0 && g[i] != 0) {
                (g[i] > 0 ? hi : lo) = r / g[i];
            } else {
                continue;
            }
            // A relative margin against rounding: the box must hold the
            // surface, not cut it.
            const double pad = 1e-9 * (std::fabs(lo) + std::fabs(hi)) + 1e-12;
            out.lo[i] = std::max(out.lo[i], lo - pad);
            out.hi[i] = std::min(out.hi[i], hi + pad);
            if (out.lo[i] > out.hi[i]) return {};
        }
    return out;
}

Bounds Quadric::bounds() const {
    Bounds box;
    bool interiorNegative;
    return ellipsoidBounds(box, interiorNegative) ? box : Bounds::infinite();
}

Bounds Quadric::insideBounds() const {
    Bounds box;
    bool interiorNegative;
    if (!ellipsoidBounds(box, interiorNegative)) return Bounds::infinite();
    return interiorNegative ? box : Bounds::infinite();
}

}  // namespace frameray::scene
