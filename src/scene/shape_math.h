// Small numeric helpers shared by the shape implementations (internal to
// scene/; not part of any shape's interface).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "scene/ray.h"

namespace frameray::scene::detail {

// The one ray-triangle test (Moller-Trumbore in double precision) of
// triangles, meshes and height fields: the ray parameter in (tMin, tMax)
// where the ray crosses triangle a b c, or false. Edges count as inside,
// so triangles sharing an edge leave no crack between them.
inline bool hitTriangle(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c, double tMin,
                        double tMax, double& t) {
    const Vec3 e1 = b - a, e2 = c - a;
    const Vec3 pv = cross(ray.direction, e2);
    const double det = dot(e1, pv);
    if (det == 0) return false;
    const double inv = 1 / det;
    const Vec3 tv = ray.origin - a;
    const double u = dot(tv, pv) * inv;
    if (u < 0 || u > 1) return false;
    const Vec3 qv = cross(tv, e1);
    const double v = dot(ray.direction, qv) * inv;
    if (v < 0 || u + v > 1) return false;
    const double hit = dot(e2, qv) * inv;
    if (!(hit > tMin && hit < tMax)) return false;
    t = hit;
    return true;
}

// Sorts the hits found, drops near-duplicates (a ray through a joint of two
// pieces finds it twice) and appends those in (tMin, tMax) to ts.
inline void appendDistinctHits(std::vector<double>& found, double tMin, double tMax,
                               std::vector<double>& ts) {
    std::sort(found.begin(), found.end());
    double last = -std::numeric_limits<double>::infinity();
    for (const double t : found) {
        if (!(t > tMin && t < tMax)) continue;
        if (t - last <= 1e-12 * std::max(1.0, std::fabs(t))) continue;
        ts.push_back(t);
        last = t;
    }
}

// Real roots of a t^2 + b t + c = 0 in increasing order; returns how many
// (0, 1 or 2). Uses the cancellation-free form (q = -(b + sign(b) sqrt(D))/2,
// roots q/a and c/q) so a root near zero keeps its precision even when the
// other one is huge. a == 0 degrades to the linear equation.
inline int solveQuadratic(double a, double b, double c, double& t0, double& t1) {
    if (a == 0) {
        if (b == 0) return 0;
        t0 = t1 = -c / b;
        return 1;
    }
    const double disc = b * b - 4 * a * c;
    if (disc < 0) return 0;
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    if (q == 0) {  // b == 0 and c == 0: a double root at 0
        t0 = t1 = 0;
        return 2;
    }
    t0 = q / a;
    t1 = c / q;
    if (t0 > t1) std::swap(t0, t1);
    return 2;
}

// Roots of |f + t g|^2 = r2: where a ray, given by its start f and
// direction g relative to a centre (or projected onto a plane around an
// axis), is at distance sqrt(r2). Measures the discriminant at the point of
// closest approach, which stays accurate when the ray starts far away.
inline bool distanceRoots(const Vec3& f, const Vec3& g, double r2, double& t0, double& t1) {
    const double a = dot(g, g);
    if (a == 0) return false;
    const double b = -dot(f, g);
    const Vec3 closest = f + g * (b / a);
    const double disc = r2 - dot(closest, closest);
    if (disc < 0) return false;
    const double c = dot(f, f) - r2;
    const double q = b + std::copysign(std::sqrt(a * disc), b);
    if (q == 0) {
        t0 = t1 = 0;
        return true;
    }
    t0 = c / q;
    t1 = q / a;
    if (t0 > t1) std::swap(t0, t1);
    return true;
}

// Appends t to ts when it lies in the open interval (tMin, tMax).
inline void keepIfInRange(double t, double tMin, double tMax, std::vector<double>& ts) {
    if (t > tMin && t < tMax) ts.push_back(t);
}

// A unit vector perpendicular to unit vector n.
inline Vec3 anyPerpendicular(const Vec3& n) {
    const Vec3 other = std::fabs(n.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    return normalize(cross(n, other));
}

}  // namespace frameray::scene::detail
