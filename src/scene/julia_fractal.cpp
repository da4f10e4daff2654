#include "scene/julia_fractal.h"

#include <algorithm>
#include <cmath>
#include <complex>

#include "scene/hit_tolerance.h"

namespace frameray::scene {

namespace {

using Complex = std::complex<double>;

// povray's tolerance: hits are refined to it, and a ray starting inside
// the set first moves twice it.
constexpr double kTolerance = 1e-7;
// povray drops intersections nearer than this to a ray's start.
constexpr double kMinDepth = kMinHitDepth;
// A tMin up to this is a ray's tolerance (povray's shadow tolerance is the
// largest), not the start of a ray continued past a hit.
constexpr double kShadowToleranceAtMost = 1.5 * kShadowTolerance;

double norm2(const std::array<double, 4>& q) {
    return q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
}

// Hypercomplex product, through the two complex components (x - w) + (y +
// z) i and (x + w) + (y - z) i, which multiply independently.
std::array<double, 4> hypercomplexProduct(const std::array<double, 4>& a,
                                          const std::array<double, 4>& b) {
    const Complex a1(a[0] - a[3], a[1] + a[2]), a2(a[0] + a[3], a[1] - a[2]);
    const Complex b1(b[0] - b[3], b[1] + b[2]), b2(b[0] + b[3], b[1] - b[2]);
    const Complex p1 = a1 * b1, p2 = a2 * b2;
    return {(p1.real() + p2.real()) / 2, (p1.imag() + p2.imag()) / 2, (p1.imag() - p2.imag()) / 2,
            (p2.real() - p1.real()) / 2};
}

}  // namespace

JuliaFractal::JuliaFractal(const std::array<double, 4>& c, Algebra algebra, Function function,
                           int maxIterations, double precision)
    : c_(c),
      algebra_(algebra),
      function_(function),
      maxIterations_(std::max(1, maxIterations)),
      stepLength_(1.0 / std::max(precision, 1e-3)) {
    if (algebra == Algebra::Quaternion) {
        const double cLength = std::sqrt(norm2(c));
        radius_ = std::min(1.0 + cLength + kTolerance, 2.0);
        bailout2_ = radius_ * radius_ + kTolerance;
    } else {
        radius_ = 4.0;
        bailout2_ = 16.0;
    }
    radius2_ = radius_ * radius_;
}

JuliaFractal::Quat JuliaFractal::step(const Quat& q) const {
    Quat r;
    if (algebra_ == Algebra::Quaternion) {
        const double a = q[0], v2 = q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
        double real, scale;
        if (function_ == Function::Sqr) {
            real = a * a - v2;
            scale = 2 * a;
        } else {
            real = a * a * a - 3 * a * v2;
            scale = 3 * a * a - v2;
        }
        r = {real, scale * q[1], scale * q[2], scale * q[3]};
    } else {
        // povray 3.7's hypercomplex `cube` squares too (measured: its
        // shapes are those of sqr; only its march steps differ, below).
        Complex z1(q[0] - q[3], q[1] + q[2]), z2(q[0] + q[3], q[1] - q[2]);
        z1 *= z1;
        z2 *= z2;
        r = {(z1.real() + z2.real()) / 2, (z1.imag() + z2.imag()) / 2, (z1.imag() - z2.imag()) / 2,
             (z2.real() - z1.real()) / 2};
    }
    for (int i = 0; i < 4; ++i) r[i] += c_[i];
    return r;
}

bool JuliaFractal::inside(const Vec3& p) const {
    Quat q = {p.x, p.y, p.z, 0};
    for (int k = 0; k < maxIterations_; ++k) {
        if (norm2(q) > bailout2_) return false;
        q = step(q);
    }
    return true;
}

bool JuliaFractal::probe(const Vec3& p, const Vec3& u, double& stepOut) const {
    stepOut = stepLength_;
    Quat q = {p.x, p.y, p.z, 0};
    // Quaternions: the product of |q(j)|^2 over the iterates before k;
    // hypercomplex: q(0) ... q(k - 1) (q(0) while k < 2) and 2^max(k, 1).
    double normProduct = 1;
    Quat product = q;
    // povray's hypercomplex `cube` leaves the 2^k out of its gradient.
    const bool doubling = function_ == Function::Sqr;
    double power = doubling ? 2 : 1;
    for (int k = 0; k < maxIterations_; ++k) {
        const double f = norm2(q);
        if (f > bailout2_) {
            if (algebra_ == Algebra::Quaternion) {
                const double base = function_ == Function::Sqr ? 2.0 : 3.0;
                stepOut = std::pow(base, -(k + 1)) * std::log(f) / std::sqrt(normProduct);
            } else {
                const Quat& a = product;
                const Quat n = {q[0] * power, q[1] * power, q[2] * power, q[3] * power};
                const Vec3 g(a[0] * n[0] + a[1] * n[1] + a[2] * n[2] + a[3] * n[3],
                             -a[1] * n[0] + a[0] * n[1] - a[3] * n[2] + a[2] * n[3],
                             -a[2] * n[0] - a[3] * n[1] + a[0] * n[2] + a[1] * n[3]);
                const double along = dot(g, u);
                if (along < -1e-8) {
                    const double s = -2.0 * along;
                    if (f > stepLength_ * s && f < 30 * stepLength_ * s) stepOut = f / s;
                }
            }
            return false;
        }
        if (k >= 1) {
            product = hypercomplexProduct(q, product);
            if (doubling) power *= 2;
        }
        normProduct *= f;
        q = step(q);
    }
    return true;
}

double JuliaFractal::potential(const Vec3& p) const {
    Quat q = {p.x, p.y, p.z, 0};
    for (int k = 0; k < maxIterations_; ++k) q = step(q);
    return q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
}

Vec3 JuliaFractal::normal(const Vec3& p) const {
    // Central differences of the potential: on the surface |q(N - 1)| is
    // the bailout radius, so |q(N)|^2 stays moderate and smooth there.
    constexpr double h = 1e-7;
    const Vec3 g{potential(p + Vec3(h, 0, 0)) - potential(p - Vec3(h, 0, 0)),
                 potential(p + Vec3(0, h, 0)) - potential(p - Vec3(0, h, 0)),
                 potential(p + Vec3(0, 0, h)) - potential(p - Vec3(0, 0, h))};
    const double len = std::sqrt(dot(g, g));
    return len > 0 ? g / len : Vec3(0, 1, 0);
}

template <typename Crossing>
void JuliaFractal::march(const Ray& ray, double tMin, double tMax, Crossing&& crossing) const {
    // povray marches the unit direction in "depth" units; t = depth / |d|.
    const double len = std::sqrt(dot(ray.direction, ray.direction));
    if (!(len > 0)) return;
    const Vec3 u = ray.direction / len;
    const double b = dot(ray.origin, u);
    const double disc = b * b - (dot(ray.origin, ray.origin) - radius2_);
    if (!(disc > 0)) return;
    const double root = std::sqrt(disc);
    const double depthMax = -b + root;
    if (depthMax < kTolerance) return;
    double depth = std::max(-b - root, kTolerance);
    if (depth / len >= tMax) return;

    Vec3 next = ray.origin + u * depth;
    double dist = 0;
    bool current = probe(next, u, dist);
    if (current) {  // starting inside: move on a little first
        next += u * (2 * kTolerance);
        depth += 2 * kTolerance;
        if (depth > depthMax) return;
        current = probe(next, u, dist);
    }
    while (depth < depthMax) {
        Vec3 point = next;
        double distNext = 0;
        bool nextInside = current;
        for (;;) {  // march to the next change
            dist = std::max(dist, stepLength_);
            depth += dist;
            if (depth > depthMax || depth / len > tMax) return;
            point = next;
            next += u * dist;
            nextInside = probe(next, u, distNext);
            if (nextInside != current) {
                depth -= dist;
                break;
            }
            dist = distNext;
        }
        // Bisection: `point` stays on the side of `current`.
        while (dist > kTolerance) {
            dist *= 0.5;
            const Vec3 mid = point + u * dist;
            if (inside(mid) == current) {
                point = mid;
                depth += dist;
                if (depth > depthMax) return;
            }
        }
        if (!current) depth += dist;  // the hit is the bracket's inside end
        const double t = depth / len;
        if (t > tMin && !crossing(t)) return;
        // povray carries on from the end of the bracket but counts depth
        // from the hit.
        dist = distNext;
        current = nextInside;
    }
}

void JuliaFractal::allHits(const Ray& ray, double tMin, double tMax,
                           std::vector<double>& ts) const {
    march(ray, tMin, tMax, [&](double t) {
        ts.push_back(t);
        return true;
    });
}

bool JuliaFractal::firstHit(const Ray& ray, double tMin, double tMax, double& t) const {
    // povray stops at the first crossing for a fractal outside CSG, and its
    // caller drops a crossing nearer than its tolerance to the ray's start
    // (1e-4, shadow rays 1e-3): a ray leaving the surface from just inside
    // meets the surface it leaves first, and so nothing. A tMin of that
    // size is such a tolerance, and the march starts at the ray's own
    // start; a ray continued past an earlier hit (a larger tMin) starts
    // there, as povray's continued rays do.
    const bool tolerance = tMin <= kShadowToleranceAtMost;
    const double start = tolerance ? 0.0 : std::max(tMin, 0.0);
    const double nearest = tolerance ? std::max(tMin, kMinDepth) : kMinDepth;
    const Ray from{ray.at(start), ray.direction};
    bool found = false;
    march(from, -kInfinity, tMax - start, [&](double hit) {
        if (hit > nearest && start + hit < tMax) {
            t = start + hit;
            found = true;
        }
        return false;
    });
    return found;
}

}  // namespace frameray::scene
