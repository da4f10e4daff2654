#include "scene/revolved_shapes.h"

#include <algorithm>
#include <cmath>

#include "scene/shape_math.h"

namespace frameray::scene {

namespace {

// povray's cylinder and cone inside tests leave out a thin skin: a second
// cylinder 1e-12 wider does not contain the first one's surface, one 1e-10
// wider does (relative to the radius and the height).
constexpr double kInsideSkin = 1e-10;

// Bounds of a circle of radius r around `center` in the plane normal to the
// unit vector `n`: along axis i it reaches r * sqrt(1 - n_i^2).
void extendByCircle(Bounds& b, const Vec3& center, const Vec3& n, double r) {
    const Vec3 e{r * std::sqrt(std::max(0.0, 1 - n.x * n.x)), r * std::sqrt(std::max(0.0, 1 - n.y * n.y)),
                 r * std::sqrt(std::max(0.0, 1 - n.z * n.z))};
    b.extend(center - e);
    b.extend(center + e);
}

// The caps of a cylinder or cone: where the ray crosses the end planes
// within the given radii.
void capHits(const ShapeAxis& axis, const Ray& ray, double baseRadius, double capRadius, double tMin, double tMax,
             std::vector<double>& ts) {
    const double da = dot(ray.direction, axis.dir);
    if (da == 0) return;
    const double wa = axis.height(ray.origin);
    const Vec3 wp = axis.offset(ray.origin);
    const Vec3 dp = ray.direction - axis.dir * da;
    const double heights[2] = {0, axis.length};
    const double radii[2] = {baseRadius, capRadius};
    for (int i = 0; i < 2; ++i) {
        if (radii[i] <= 0) continue;
        const double t = (heights[i] - wa) / da;
        const Vec3 off = wp + dp * t;
        if (dot(off, off) <= radii[i] * radii[i]) detail::keepIfInRange(t, tMin, tMax, ts);
    }
}

// Sorts the hits appended since `from` (at most four) and drops exact
// duplicates, which a ray grazing an edge produces.
void finishHits(std::vector<double>& ts, size_t from) {
    std::sort(ts.begin() + static_cast<std::ptrdiff_t>(from), ts.end());
    ts.erase(std::unique(ts.begin() + static_cast<std::ptrdiff_t>(from), ts.end()), ts.end());
}

// Which part of a capped shape a surface point lies on, by the smallest
// distance: side (0), base cap (1) or end cap (2).
int closestPart(double sideDistance, double h, double length) {
    const double dBase = std::fabs(h), dCap = std::fabs(h - length);
    if (sideDistance <= dBase && sideDistance <= dCap) return 0;
    return dBase <= dCap ? 1 : 2;
}

}  // namespace

ShapeAxis::ShapeAxis(const Vec3& b, const Vec3& cap) : base(b) {
    const Vec3 d = cap - b;
    length = frameray::length(d);
    dir = d / length;
}

// --- Cylinder -----------------------------------------------------------------

void Cylinder::allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const {
    const size_t from = ts.size();
    const double da = dot(ray.direction, axis_.dir);
    const double wa = axis_.height(ray.origin);
    const Vec3 wp = axis_.offset(ray.origin);
    const Vec3 dp = ray.direction - axis_.dir * da;
    double t0, t1;
    if (detail::distanceRoots(wp, dp, radius_ * radius_, t0, t1)) {
        for (const double t : {t0, t1}) {
            const double h = wa + t * da;
            if (h >= 0 && h <= axis_.length) detail::keepIfInRange(t, tMin, tMax, ts);
        }
    }
    if (!open_) capHits(axis_, ray, radius_, radius_, tMin, tMax, ts);
    finishHits(ts, from);
}

Vec3 Cylinder::normal(const Vec3& p) const {
    const Vec3 off = axis_.offset(p);
    const double h = axis_.height(p);
    const int part = open_ ? 0 : closestPart(std::fabs(length(off) - radius_), h, axis_.length);
    if (part == 1) return -axis_.dir;
    if (part == 2) return axis_.dir;
    return normalize(off);
}

bool Cylinder::inside(const Vec3& p) const {
    // `open` removes the caps from the surface, not from the inside.
    const double h = axis_.height(p) / axis_.length;
    const Vec3 off = axis_.offset(p);
    return h > kInsideSkin && h < 1 - kInsideSkin && dot(off, off) < radius_ * radius_ * (1 - kInsideSkin);
}

Bounds Cylinder::bounds() const {
    Bounds b;
    extendByCircle(b, axis_.base, axis_.dir, radius_);
    extendByCircle(b, axis_.base + axis_.dir * axis_.length, axis_.dir, radius_);
    return b;
}

// --- Cone ---------------------------------------------------------------------

void Cone::allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const {
    const size_t from = ts.size();
    const double da = dot(ray.direction, axis_.dir);
    const double wa = axis_.height(ray.origin);
    const Vec3 wp = axis_.offset(ray.origin);
    const Vec3 dp = ray.direction - axis_.dir * da;
    // |wp + t dp|^2 = (s0 + t s1)^2, the radius at the ray's height.
    const double s0 = radiusAt(wa), s1 = slope_ * da;
    const double a = dot(dp, dp) - s1 * s1;
    const double b = 2 * (dot(wp, dp) - s0 * s1);
    const double c = dot(wp, wp) - s0 * s0;
    double t0, t1;
    const int n = detail::solveQuadratic(a, b, c, t0, t1);
    for (int i = 0; i < n; ++i) {
        const double t = i == 0 ? t0 : t1;
        const double h = wa + t * da;
        // The height range also rejects the mirror cone beyond the apex.
        if (h >= 0 && h <= axis_.length) detail::keepIfInRange(t, tMin, tMax, ts);
    }
    if (!open_) capHits(axis_, ray, r1_, r2_, tMin, tMax, ts);
    finishHits(ts, from);
}

Vec3 Cone::normal(const Vec3& p) const {
    const Vec3 off = axis_.offset(p);
    const double h = axis_.height(p);
    const double r = length(off);
    // Distance to the side, measured perpendicular to the slanted surface.
    const double sideDistance = std::fabs(r - radiusAt(h)) / std::sqrt(1 + slope_ * slope_);
    const int part = open_ ? 0 : closestPart(sideDistance, h, axis_.length);
    if (part == 1) return -axis_.dir;
    if (part == 2) return axis_.dir;
    // Gradient of |offset| - radius(h).
    const Vec3 radial = r > 0 ? off / r : Vec3();
    return normalize(radial - axis_.dir * slope_);
}

bool Cone::inside(const Vec3& p) const {
    const double h = axis_.height(p);
    const double hn = h / axis_.length;
    const Vec3 off = axis_.offset(p);
    const double r = radiusAt(h);
    return hn > kInsideSkin && hn < 1 - kInsideSkin && dot(off, off) < r * r * (1 - kInsideSkin);
}

Bounds Cone::bounds() const {
    Bounds b;
    extendByCircle(b, axis_.base, axis_.dir, r1_);
    extendByCircle(b, axis_.base + axis_.dir * axis_.length, axis_.dir, r2_);
    return b;
}

}  // namespace frameray::scene
