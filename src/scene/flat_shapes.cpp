#include "scene/flat_shapes.h"

#include <cmath>

#include "scene/shape_math.h"

namespace frameray::scene {

// --- Disc -----------------------------------------------------------------------

Disc::Disc(const Vec3& center, const Vec3& normal, double radius, double holeRadius)
    : center_(center),
      normal_(normalize(normal)),
      radius2_(radius * radius),
      hole2_(holeRadius * holeRadius) {}

void Disc::allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const {
    const double denom = dot(ray.direction, normal_);
    if (denom == 0) return;
    const double t = dot(center_ - ray.origin, normal_) / denom;
    if (!(t > tMin && t < tMax)) return;
    const Vec3 off = ray.at(t) - center_;
    const double r2 = dot(off, off);
    if (r2 <= radius2_ && r2 >= hole2_) ts.push_back(t);
}

Bounds Disc::bounds() const {
    // The circle's box, thickened by 0.001 along the normal both ways: a
    // povray disc's bounding box is that thick, which shows in CSG
    // (intersection { disc { 0, y, 2 } box { -1, 1 } } seen edge-on keeps a
    // 0.001-high band of the box's front face below y = 0).
    const double r = std::sqrt(radius2_);
    const Vec3& n = normal_;
    const Vec3 e = Vec3{r * std::sqrt(std::max(0.0, 1 - n.x * n.x)),
                        r * std::sqrt(std::max(0.0, 1 - n.y * n.y)),
                        r * std::sqrt(std::max(0.0, 1 - n.z * n.z))} +
                   Vec3{std::fabs(n.x), std::fabs(n.y), std::fabs(n.z)} * kThickness;
    return {center_ - e, center_ + e};
}

// --- Triangle -------------------------------------------------------------------

Triangle::Triangle(const Vec3& a, const Vec3& b, const Vec3& c) : a_(a), b_(b), c_(c) {
    const Vec3 n = cross(b - a, c - a);
    degenerate_ = dot(n, n) == 0;
}

bool Triangle::firstHit(const Ray& ray, double tMin, double tMax, double& t) const {
    if (degenerate_) return false;
    return detail::hitTriangle(ray, a_, b_, c_, tMin, tMax, t);
}

void Triangle::allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const {
    double t;
    if (firstHit(ray, tMin, tMax, t)) ts.push_back(t);
}

Bounds Triangle::bounds() const {
    Bounds b;
    if (degenerate_) return b;
    b.extend(a_);
    b.extend(b_);
    b.extend(c_);
    return b;
}

void Triangle::weights(const Vec3& p, double& wb, double& wc) const {
    // Solve p - a = wb (b - a) + wc (c - a) in the least-squares sense,
    // which is exact for points in the plane.
    const Vec3 e1 = b_ - a_, e2 = c_ - a_, w = p - a_;
    const double d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2);
    const double w1 = dot(w, e1), w2 = dot(w, e2);
    const double det = d11 * d22 - d12 * d12;
    if (det == 0) {
        wb = wc = 0;
        return;
    }
    wb = (d22 * w1 - d12 * w2) / det;
    wc = (d11 * w2 - d12 * w1) / det;
}

// --- SmoothTriangle ---------------------------------------------------------------

SmoothTriangle::SmoothTriangle(const Vec3& a, const Vec3& na, const Vec3& b, const Vec3& nb,
                               const Vec3& c, const Vec3& nc)
    : Triangle(a, b, c), na_(normalize(na)), nb_(normalize(nb)), nc_(normalize(nc)) {}

Vec3 SmoothTriangle::normal(const Vec3& p) const {
    double wb, wc;
    weights(p, wb, wc);
    const Vec3 n = na_ * (1 - wb - wc) + nb_ * wb + nc_ * wc;
    return dot(n, n) > 0 ? normalize(n) : Triangle::normal(p);
}

}  // namespace frameray::scene
