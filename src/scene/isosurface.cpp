#include "scene/isosurface.h"

#include <algorithm>
#include <cmath>

#include "scene/implicit_search.h"
#include "scene/shape_math.h"

namespace frameray::scene {

namespace {

constexpr double kBoundHuge = 2.0e10;  // povray's cap on a ray's far end

// povray 3.7's root search along one ray (R. Suzuki's method 2), step for
// step, so hit points land where povray's do: halve the interval while the
// values at its ends, less the drop max_gradient allows over it, leave room
// for a root; an interval shorter than `accuracy` whose far end is inside
// is the hit, and the hit is that far end, not the root (up to `accuracy`
// beyond it). Values are multiplied by `sign`, which flips after each
// crossing so that the search always looks for a change to negative.
struct RootSearch {
    const Isosurface& shape;
    const Ray& ray;
    double accuracy;
    double sign = 1;
    double root = 0;

    double at(double t) const { return sign * shape.value(ray.at(t)); }

    bool halve(double t1, double f1, double t2, double f2, double drop, double width) {
        if (width < accuracy) {
            if (f2 >= 0) return false;
            root = t2;
            return true;
        }
        if (f1 + f2 - drop >= 0) return false;
        width *= 0.5;
        drop *= 0.5;
        const double tm = t1 + width;
        const double fm = at(tm);
        return halve(t1, f1, tm, fm, drop, width) || halve(tm, fm, t2, f2, drop, width);
    }

    // The first crossing in [t1, t2]; an open shape's search starting
    // inside the function flips the sign for good.
    bool find(double t1, double t2, double maxGradient, bool open) {
        double f1 = at(t1);
        if (open && f1 < 0) {
            sign = -sign;
            f1 = -f1;
        }
        const double f2 = at(t2);
        const double width = t2 - t1;
        return halve(t1, f1, t2, f2, maxGradient * length(ray.direction) * width, width);
    }
};

}  // namespace

bool Isosurface::leaves(const Vec3& p, const Vec3& direction) const {
    const double h = s_.accuracy;
    const double f0 = value(p);
    Vec3 g;
    for (int a = 0; a < 3; ++a) {
        Vec3 q = p;
        q[a] += h;
        g[a] = value(q) - f0;
    }
    return dot(g, direction) > 0;
}

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
    double depth1, depth2;
    if (!containerInterval(ray, depth1, depth2) || !(depth2 > tMin)) return;
    depth1 = std::max(depth1, tMin);
    const double acc = s_.accuracy, maxg = s_.maxGradient;
    // How close to the surface a start point counts as on it, and how far
    // a search steps off it (povray's 4 and 5 accuracies).
    const double onSurface = maxg * acc * 4.0, stepOff = acc * 5.0;
    const size_t from = ts.size();
    int traced = 0;
    RootSearch search{*this, ray, acc};
    bool startsInBand = false;
    if (!s_.open) {
        // The container's face is the surface where the function is inside.
        if (depth1 > acc) {
            if (value(ray.at(depth1)) < 0) {
                ts.push_back(depth1);
                ++traced;
                search.sign = -1;
            }
        } else {
            startsInBand = std::fabs(value(ray.at(depth1))) < onSurface;
            if (value(ray.at(depth1)) < onSurface) {
                depth1 = stepOff;
                if (value(ray.at(depth1)) < 0) search.sign = -1;
            }
            if (value(ray.at(depth2)) < 0) ts.push_back(depth2);
        }
    }
    double tmax = depth2 = std::min(depth2, kBoundHuge);
    double tmin = depth1 = std::min(depth2, depth1);
    if (tmax - tmin < acc) {
        if (ts.size() > from) ts.pop_back();
        return;
    }
    // A ray starting on the surface steps off it first.
    bool startsOnSurface = startsInBand;
    if (depth1 < acc && search.sign == 1 && std::fabs(value(ray.at(tmin))) < onSurface) {
        startsOnSurface = true;
        tmin = stepOff;
        if (value(ray.at(tmin)) < 0) search.sign = -1;
    }
    // Where povray departs from itself: its hit points lie up to `accuracy`
    // inside the surface, so a ray leaving one (a shadow or reflected ray)
    // starts inside the function and, grazing, is still inside after the
    // step off; povray then reports the surface it leaves as a hit (self
    // shadowing speckles: 6 and 18 of them in tests/stability/sweep_cases.pov
    // cases 4 and 5 against accuracy 1e-6). When the function grows along
    // the ray there, the first crossing out is that same surface: skip it.
    bool skipExit = startsOnSurface && search.sign == -1 && leaves(ray.at(depth1), ray.direction);
    for (; traced < std::max(1, s_.maxTrace); ++traced) {
        if (!search.find(tmin, tmax, maxg, s_.open)) break;
        if (skipExit) {
            skipExit = false;
            --traced;
            tmin = search.root + stepOff;
            if (tmax - tmin < acc) break;
            search.sign = -search.sign;
            continue;
        }
        ts.push_back(search.root);
        tmin = search.root + stepOff;
        if (tmax - tmin < acc) break;
        search.sign = -search.sign;
    }
    // Keep what lies in (tMin, tMax), nearest first.
    size_t kept = from;
    for (size_t i = from; i < ts.size(); ++i)
        if (ts[i] > tMin && ts[i] < tMax) ts[kept++] = ts[i];
    ts.resize(kept);
    std::sort(ts.begin() + static_cast<std::ptrdiff_t>(from), ts.end());
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
    // povray's forward differences over the accuracy, (1, 0, 0) where the
    // function is flat.
    const double h = s_.accuracy;
    auto raw = [&](const Vec3& q) {
        const double args[3] = {q.x, q.y, q.z};
        return s_.function->eval(args);
    };
    const double f0 = raw(p);
    Vec3 g;
    for (int a = 0; a < 3; ++a) {
        Vec3 q = p;
        q[a] += h;
        g[a] = raw(q) - f0;
    }
    if (g.x == 0 && g.y == 0 && g.z == 0) g.x = 1;
    const double len = length(g);
    if (!(len > 0) || !std::isfinite(len)) return Vec3(0, 1, 0);
    return g * (1.0 / len);
}

bool Isosurface::inside(const Vec3& p) const {
    return insideContainer(p) && value(p) < 0;
}

Bounds Isosurface::bounds() const {
    if (s_.sphereContainer) return {s_.center - Vec3(s_.radius), s_.center + Vec3(s_.radius)};
    return {s_.boxLo, s_.boxHi};
}

}  // namespace frameray::scene
