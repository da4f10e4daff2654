#include "scene/julia_fractal.h"

#include <algorithm>
#include <cmath>
#include <complex>

namespace frameray::scene {

namespace {

using Complex = std::complex<double>;

// Bisection steps refining a crossing: the bracket starts one march step
// wide, so 40 halvings reach well below any pixel.
constexpr int kBisections = 40;

}  // namespace

JuliaFractal::JuliaFractal(const std::array<double, 4>& c, Algebra algebra, Function function,
                           int maxIterations, double precision)
    : c_(c),
      algebra_(algebra),
      function_(function),
      maxIterations_(std::max(1, maxIterations)),
      stepLength_(1.0 / std::max(precision, 1e-3)) {
    const double cLength = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2] + c[3] * c[3]);
    radius_ = algebra == Algebra::Quaternion ? 1.0 + cLength : 4.0;
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
        Complex z1(q[0] - q[3], q[1] + q[2]), z2(q[0] + q[3], q[1] - q[2]);
        if (function_ == Function::Sqr) {
            z1 *= z1;
            z2 *= z2;
        } else {
            z1 = z1 * z1 * z1;
            z2 = z2 * z2 * z2;
        }
        r = {(z1.real() + z2.real()) / 2, (z1.imag() + z2.imag()) / 2, (z1.imag() - z2.imag()) / 2,
             (z2.real() - z1.real()) / 2};
    }
    for (int i = 0; i < 4; ++i) r[i] += c_[i];
    return r;
}

bool JuliaFractal::inside(const Vec3& p) const {
    Quat q = {p.x, p.y, p.z, 0};
    for (int k = 0; k < maxIterations_; ++k) {
        if (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3] > radius2_) return false;
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
    // The part of the ray inside the bounding sphere.
    const double dd = dot(ray.direction, ray.direction);
    if (!(dd > 0)) return;
    const double b = dot(ray.origin, ray.direction) / dd;
    const double disc = b * b - (dot(ray.origin, ray.origin) - radius2_) / dd;
    if (disc <= 0) return;
    const double root = std::sqrt(disc);
    const double t0 = std::max(tMin, -b - root), t1 = std::min(tMax, -b + root);
    if (!(t0 < t1)) return;
    const double dt = stepLength_ / std::sqrt(dd);  // 1 / precision in object space
    double prevT = t0;
    bool prevInside = inside(ray.at(t0));
    // Outside the bounding sphere nothing is inside (|q(0)| > R), so a set
    // reaching the sphere (c = 0: the unit ball) is entered and left there.
    const bool entersSphere = t0 > tMin, leavesSphere = t1 < tMax;
    if (prevInside && entersSphere && !crossing(t0)) return;
    for (int k = 1;; ++k) {
        const double t = std::min(t1, t0 + k * dt);
        const bool in = inside(ray.at(t));
        if (in != prevInside) {
            double lo = prevT, hi = t;
            for (int i = 0; i < kBisections; ++i) {
                const double mid = 0.5 * (lo + hi);
                (inside(ray.at(mid)) == prevInside ? lo : hi) = mid;
            }
            if (!crossing(hi)) return;
        }
        if (t >= t1) {
            if (in && leavesSphere) crossing(t1);
            return;
        }
        prevT = t;
        prevInside = in;
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
    bool found = false;
    march(ray, tMin, tMax, [&](double hit) {
        t = hit;
        found = true;
        return false;
    });
    return found;
}

}  // namespace frameray::scene
