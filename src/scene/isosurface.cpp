#include "scene/isosurface.h"

#include <algorithm>
#include <cmath>

#include "scene/implicit_search.h"
#include "scene/shape_math.h"

namespace frameray::scene {

namespace {

// The search along one ray for where the function's sign changes. Values
// are taken relative to the sign where the search starts (`sign` makes
// them positive there), so only real crossings count, not near misses.
struct RootSearch {
    const Isosurface& shape;
    const Ray& ray;
    double lipschitz;  // bound on |d value / dt| along this ray
    double minStep;    // piece length in t below which a crossing is pinned
    double sign = 1;

    double at(double t) const { return sign * shape.value(ray.at(t)); }

    // The first crossing in (a, b], whose end values are fa > 0 and fb;
    // kInfinity when none is found.
    double first(double a, double fa, double b, double fb) const {
        const double dt = b - a;
        // With |f'| <= L the values on the piece stay above
        // (fa + fb - L dt) / 2.
        if (fb >= 0 && fa + fb > lipschitz * dt) return kInfinity;
        if (dt <= minStep) {
            if (fb >= 0) return kInfinity;
            return detail::refineRoot([&](double t) { return at(t); }, a, fa, b, fb);
        }
        const double m = 0.5 * (a + b);
        const double fm = at(m);
        const double left = first(a, fa, m, fm);  // certain to find one when fm < 0
        if (left < kInfinity || fm < 0) return left;
        return first(m, fm, b, fb);
    }
};

}  // namespace

bool Isosurface::containerInterval(const Ray& ray, double& t0, double& t1) const {
    if (s_.sphereContainer)
        return detail::distanceRoots(ray.origin - s_.center, ray.direction, s_.radius * s_.radius,
                                     t0, t1);
    return detail::clipToBox(ray, s_.boxLo, s_.boxHi, t0, t1);
}

bool Isosurface::insideContainer(const Vec3& p) const {
    if (s_.sphereContainer) {
        const Vec3 d = p - s_.center;
        return dot(d, d) <= s_.radius * s_.radius;
    }
    return p.x >= s_.boxLo.x && p.x <= s_.boxHi.x && p.y >= s_.boxLo.y && p.y <= s_.boxHi.y &&
           p.z >= s_.boxLo.z && p.z <= s_.boxHi.z;
}

double Isosurface::containerDistance(const Vec3& p) const {
    if (s_.sphereContainer) return std::fabs(length(p - s_.center) - s_.radius);
    double d = kInfinity;
    for (int a = 0; a < 3; ++a)
        d = std::min({d, std::fabs(p[a] - s_.boxLo[a]), std::fabs(p[a] - s_.boxHi[a])});
    return d;
}

void Isosurface::allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const {
    double c0, c1;
    if (!containerInterval(ray, c0, c1)) return;
    const double speed = length(ray.direction);
    if (speed == 0) return;
    const double minStep = s_.accuracy / speed;
    const bool entersContainer = c0 > tMin;
    // A ray starting inside the container (a shadow or reflected ray from
    // the surface) skips its first `accuracy` of length: its start lies on
    // the surface, and its sign there is noise.
    double a = entersContainer ? c0 : tMin + minStep;
    const double b = std::min(c1, tMax);
    if (!(a < b)) return;

    const size_t limit = static_cast<size_t>(std::max(1, s_.maxTrace));
    size_t count = 0;
    auto report = [&](double t) {
        ts.push_back(t);
        return ++count < limit;
    };
    RootSearch search{*this, ray, s_.maxGradient * speed, minStep};
    double fa = value(ray.at(a));
    // Entering the container where the function is inside: the
    // container's face is the surface there.
    if (!s_.open && entersContainer && fa < 0 && !report(c0)) return;
    bool insideNow = fa < 0;
    for (;;) {
        search.sign = insideNow ? -1 : 1;
        const double t = search.first(a, search.sign * fa, b, search.at(b));
        if (t == kInfinity) break;
        if (!report(t)) return;
        // Carry on beyond the crossing, from the far side of its piece.
        insideNow = !insideNow;
        a = std::min(b, t + minStep);
        if (!(a < b)) break;
        fa = value(ray.at(a));
        if ((fa < 0) != insideNow) insideNow = fa < 0;  // a second crossing within the step
    }
    if (!s_.open && c1 < tMax && insideNow) report(c1);
}

Vec3 Isosurface::normal(const Vec3& p) const {
    const double v = value(p);
    // On the container's face, inside the function: the face's normal.
    const double scale = s_.sphereContainer ? s_.radius : length(s_.boxHi - s_.boxLo);
    if (!s_.open && v < 0 && containerDistance(p) <= 1e-9 * scale) {
        if (s_.sphereContainer) return normalize(p - s_.center);
        int axis = 0;
        double best = kInfinity, sign = 1;
        for (int a = 0; a < 3; ++a) {
            const double dl = std::fabs(p[a] - s_.boxLo[a]), dh = std::fabs(p[a] - s_.boxHi[a]);
            if (dl < best) best = dl, axis = a, sign = -1;
            if (dh < best) best = dh, axis = a, sign = 1;
        }
        Vec3 n;
        n[axis] = sign;
        return n;
    }
    // The function's gradient by central differences over the accuracy.
    const double h = s_.accuracy;
    Vec3 g;
    for (int a = 0; a < 3; ++a) {
        Vec3 lo = p, hi = p;
        lo[a] -= h;
        hi[a] += h;
        g[a] = value(hi) - value(lo);
    }
    const double len = length(g);
    if (!(len > 0) || !std::isfinite(len)) return Vec3(0, 1, 0);
    return g / len;
}

bool Isosurface::inside(const Vec3& p) const {
    return insideContainer(p) && value(p) < 0;
}

Bounds Isosurface::bounds() const {
    if (s_.sphereContainer) return {s_.center - Vec3(s_.radius), s_.center + Vec3(s_.radius)};
    return {s_.boxLo, s_.boxHi};
}

}  // namespace frameray::scene
