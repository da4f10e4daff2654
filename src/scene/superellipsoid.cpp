#include "scene/superellipsoid.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "scene/implicit_search.h"

namespace frameray::scene {

namespace {

// Samples per piece of the ray between the planes where the function's
// form changes; two roots closer than a piece's 1/kSamples (a ray grazing
// the silhouette) are missed together, which is invisible at pixel scale.
constexpr int kSamples = 12;

}  // namespace

Superellipsoid::Superellipsoid(double e, double n)
    : e_(e), n_(n), xyPower_(2 / e), zPower_(2 / n), outerPower_(e / n) {}

double Superellipsoid::implicit(const Vec3& p) const {
    const double r = std::pow(std::fabs(p.x), xyPower_) + std::pow(std::fabs(p.y), xyPower_);
    return std::pow(r, outerPower_) + std::pow(std::fabs(p.z), zPower_) - 1;
}

void Superellipsoid::allHits(const Ray& ray, double tMin, double tMax,
                             std::vector<double>& ts) const {
    // A hair beyond the unit cube, so surface points on its faces (e or n
    // near 0 makes the shape a cube) are bracketed.
    constexpr double kMargin = 1e-9;
    double t0, t1;
    if (!detail::clipToBox(ray, Vec3(-1 - kMargin), Vec3(1 + kMargin), t0, t1)) return;
    t0 = std::max(t0, tMin);
    t1 = std::min(t1, tMax);
    if (!(t0 < t1)) return;

    // The function is smooth between the coordinate planes and the planes
    // x = +-y, where its absolute values and the larger of |x|, |y| switch.
    std::array<double, 7> cuts{};
    int nCuts = 0;
    cuts[nCuts++] = t0;
    auto addCut = [&](double num, double den) {
        if (den == 0) return;
        const double t = num / den;
        if (t > t0 && t < t1) cuts[nCuts++] = t;
    };
    const Vec3& o = ray.origin;
    const Vec3& d = ray.direction;
    addCut(-o.x, d.x);
    addCut(-o.y, d.y);
    addCut(-o.z, d.z);
    addCut(o.y - o.x, d.x - d.y);
    addCut(-o.y - o.x, d.x + d.y);
    cuts[nCuts++] = t1;
    // Insertion sort of at most seven values.
    for (int i = 1; i < nCuts; ++i)
        for (int j = i; j > 0 && cuts[j - 1] > cuts[j]; --j) std::swap(cuts[j - 1], cuts[j]);

    auto f = [&](double t) { return implicit(ray.at(t)); };
    double prevT = t0, prevF = f(t0);
    for (int c = 0; c + 1 < nCuts; ++c) {
        const double a = cuts[c], b = cuts[c + 1];
        if (!(b > a)) continue;
        for (int i = 1; i <= kSamples; ++i) {
            const double t = i == kSamples ? b : a + (b - a) * i / kSamples;
            const double ft = f(t);
            if ((ft < 0) != (prevF < 0)) {
                const double root = detail::refineRoot(f, prevT, prevF, t, ft);
                if (root > tMin && root < tMax && (ts.empty() || root > ts.back()))
                    ts.push_back(root);
            }
            prevT = t;
            prevF = ft;
        }
    }
}

Vec3 Superellipsoid::normal(const Vec3& p) const {
    // Gradient of the implicit function, without its common factor 2/n:
    //   d/dx = r^(e/n - 1) |x|^(2/e - 1) sign(x),   d/dz = |z|^(2/n - 1) sign(z)
    // with r = |x|^(2/e) + |y|^(2/e). A zero coordinate contributes nothing
    // (the exact limit when the power exceeds 1; an edge of the surface
    // otherwise, where any choice is as good).
    const double ax = std::fabs(p.x), ay = std::fabs(p.y), az = std::fabs(p.z);
    const double r = std::pow(ax, xyPower_) + std::pow(ay, xyPower_);
    Vec3 g;
    if (r > 0) {
        const double common = std::pow(r, outerPower_ - 1);
        if (ax > 0) g.x = std::copysign(common * std::pow(ax, xyPower_ - 1), p.x);
        if (ay > 0) g.y = std::copysign(common * std::pow(ay, xyPower_ - 1), p.y);
    }
    if (az > 0) g.z = std::copysign(std::pow(az, zPower_ - 1), p.z);
    if (std::isinf(g.x) || std::isinf(g.y) || std::isinf(g.z)) {
        // A power below zero at a tiny coordinate (a sharp edge): the
        // infinite terms dominate.
        auto dominant = [](double v) { return std::isinf(v) ? std::copysign(1.0, v) : 0.0; };
        g = Vec3(dominant(g.x), dominant(g.y), dominant(g.z));
    }
    if (g.x == 0 && g.y == 0 && g.z == 0) return normalize(p);
    return normalize(g);
}

}  // namespace frameray::scene
