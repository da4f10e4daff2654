// Helpers for shapes found by searching a function along the ray
// (superellipsoid, isosurface): clipping the ray to a container and
// refining a bracketed root (internal to scene/).
#pragma once

#include <algorithm>
#include <cmath>

#include "scene/ray.h"

namespace frameray::scene::detail {

// The ray's parameter interval inside the box lo..hi; false when it misses.
inline bool clipToBox(const Ray& ray, const Vec3& lo, const Vec3& hi, double& t0, double& t1) {
    t0 = -kInfinity;
    t1 = kInfinity;
    for (int a = 0; a < 3; ++a) {
        const double o = ray.origin[a], d = ray.direction[a];
        if (d == 0) {
            if (o < lo[a] || o > hi[a]) return false;
            continue;
        }
        double ta = (lo[a] - o) / d, tb = (hi[a] - o) / d;
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    return t0 <= t1;
}

// Refines a root of f in [a, b] where fa and fb have opposite signs (or one
// is zero) by the Illinois variant of false position, falling back to
// bisection when it stalls; stops at a relative width of about 1e-13.
template <typename F>
double refineRoot(const F& f, double a, double fa, double b, double fb) {
    if (fa == 0) return a;
    if (fb == 0) return b;
    int side = 0;
    const double tolerance = 1e-13 * std::max({1.0, std::fabs(a), std::fabs(b)});
    for (int i = 0; i < 100 && b - a > tolerance; ++i) {
        double c = (a * fb - b * fa) / (fb - fa);
        // Every fourth step bisects, so a one-sided approach still shrinks.
        if (!(c > a && c < b) || i % 4 == 3) c = 0.5 * (a + b);
        const double fc = f(c);
        if (fc == 0) return c;
        if ((fc < 0) == (fa < 0)) {
            a = c;
            fa = fc;
            if (side == -1) fb *= 0.5;
            side = -1;
        } else {
            b = c;
            fb = fc;
            if (side == 1) fa *= 0.5;
            side = 1;
        }
    }
    return std::fabs(fa) < std::fabs(fb) ? a : b;
}

}  // namespace frameray::scene::detail
