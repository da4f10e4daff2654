#include "scene/shapes.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "scene/scratch.h"
#include "scene/shape_math.h"

namespace frameray::scene {

bool Shape::firstHit(const Ray& ray, double tMin, double tMax, double& t) const {
    ScratchVector<double> scratch;
    std::vector<double>& ts = scratch.get();
    allHits(ray, tMin, tMax, ts);
    if (ts.empty()) return false;
    t = ts.front();
    return true;
}

// --- Sphere -----------------------------------------------------------------

namespace {

// Both roots of |o + t d - c|^2 = r^2, in increasing order. Near the
// sphere, povray's arithmetic (closest approach along the unit direction,
// then the half chord): its rounding decides on which side of a pattern
// boundary lying on the surface a hit falls (measured: an onion with
// rings at radius 1 on a unit sphere, textures/pigments/cantelop.pov).
// Far away, where that form cancels catastrophically, the cancellation-
// free formulation of shape_math.h.
bool sphereRoots(const Ray& ray, const Vec3& center, double radius, double& t0, double& t1) {
    const Vec3 oc = center - ray.origin;
    const double r2 = radius * radius;
    const double ocSquared = dot(oc, oc);
    const double a = dot(ray.direction, ray.direction);
    if (a == 0 || !(ocSquared <= 1e6 * r2))
        return detail::distanceRoots(ray.origin - center, ray.direction, r2, t0, t1);
    // A direction unit to rounding is used as it is, as povray does.
    const bool unitLength = std::fabs(a - 1) < 1e-9;
    const double length = unitLength ? 1 : std::sqrt(a);
    const Vec3 unit = unitLength ? ray.direction : ray.direction * (1 / length);
    const double closest = dot(oc, unit);
    const double halfChord2 = r2 - ocSquared + closest * closest;
    if (halfChord2 < 0) return false;
    const double halfChord = std::sqrt(halfChord2);
    t0 = (closest - halfChord) / length;
    t1 = (closest + halfChord) / length;
    return true;
}

}  // namespace

void Sphere::allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const {
    double t0, t1;
    if (!sphereRoots(ray, center_, radius_, t0, t1)) return;
    if (t0 > tMin && t0 < tMax) ts.push_back(t0);
    if (t1 > tMin && t1 < tMax && t1 != t0) ts.push_back(t1);
}

bool Sphere::firstHit(const Ray& ray, double tMin, double tMax, double& t) const {
    double t0, t1;
    if (!sphereRoots(ray, center_, radius_, t0, t1)) return false;
    if (t0 > tMin && t0 < tMax) {
        t = t0;
        return true;
    }
    if (t1 > tMin && t1 < tMax) {
        t = t1;
        return true;
    }
    return false;
}

// povray 3.7's sphere uv (measured): u the turns around y from +x towards
// +z, v the latitude from the south pole (0) to the north pole (1).
bool Sphere::uv(const Vec3& p, double& u, double& v) const {
    const Vec3 d = p - center_;
    const double len = length(d);
    double angle = std::atan2(d.z, d.x) / (2 * std::numbers::pi);
    if (angle < 0) angle += 1;
    u = angle;
    v = len > 0 ? 0.5 + std::asin(std::clamp(d.y / len, -1.0, 1.0)) / std::numbers::pi : 0.5;
    return true;
}

bool Sphere::inside(const Vec3& p) const {
    const Vec3 d = p - center_;
    return dot(d, d) < radius_ * radius_;
}

Bounds Sphere::bounds() const {
    return {center_ - Vec3(radius_), center_ + Vec3(radius_)};
}

// --- Plane ------------------------------------------------------------------

Plane::Plane(const Vec3& normal, double distance) {
    // `plane { N, D }` lies D units from the origin along the normalised N,
    // whatever N's length (checked against povray 3.7: <2,0,0>, 3 is x = 3).
    normal_ = normalize(normal);
    distance_ = distance;
}

bool Plane::firstHit(const Ray& ray, double tMin, double tMax, double& t) const {
    const double denom = dot(normal_, ray.direction);
    if (denom == 0) return false;
    t = (distance_ - dot(normal_, ray.origin)) / denom;
    return t > tMin && t < tMax;
}

Bounds Plane::insideBounds() const {
    int axis = -1, nonZero = 0;
    for (int i = 0; i < 3; ++i)
        if (normal_[i] != 0) {
            axis = i;
            ++nonZero;
        }
    Bounds b = Bounds::infinite();
    if (nonZero != 1) return b;
    // normal_[axis] is +1 or -1 here.
    const double limit = (distance_ + kInsideMargin) / normal_[axis];
    if (normal_[axis] > 0)
        b.hi[axis] = limit;
    else
        b.lo[axis] = limit;
    return b;
}

void Plane::allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const {
    double t;
    if (firstHit(ray, tMin, tMax, t)) ts.push_back(t);
}

// --- Box --------------------------------------------------------------------

bool Box::slabs(const Ray& ray, double& tNear, double& tFar) const {
    tNear = -kInfinity;
    tFar = kInfinity;
    for (int axis = 0; axis < 3; ++axis) {
        const double o = ray.origin[axis], d = ray.direction[axis];
        if (d == 0) {
            if (o < lo_[axis] || o > hi_[axis]) return false;
            continue;
        }
        double t0 = (lo_[axis] - o) / d, t1 = (hi_[axis] - o) / d;
        if (t0 > t1) std::swap(t0, t1);
        tNear = maxOf(tNear, t0);
        tFar = minOf(tFar, t1);
        if (tNear > tFar) return false;
    }
    return true;
}

void Box::allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const {
    double tNear, tFar;
    if (!slabs(ray, tNear, tFar)) return;
    if (tNear > tMin && tNear < tMax) ts.push_back(tNear);
    if (tFar > tMin && tFar < tMax && tFar != tNear) ts.push_back(tFar);
}

bool Box::firstHit(const Ray& ray, double tMin, double tMax, double& t) const {
    double tNear, tFar;
    if (!slabs(ray, tNear, tFar)) return false;
    if (tNear > tMin && tNear < tMax) {
        t = tNear;
        return true;
    }
    if (tFar > tMin && tFar < tMax && tFar != tNear) {
        t = tFar;
        return true;
    }
    return false;
}

Vec3 Box::normal(const Vec3& p) const {
    // The face whose plane the point lies closest to, relative to the box
    // size so thin boxes pick the right face.
    int bestAxis = 0;
    double bestDist = kInfinity, sign = 1;
    for (int axis = 0; axis < 3; ++axis) {
        // A box flat along an axis (corners sharing a coordinate) is all
        // that face, whatever rounding left in the point (measured:
        // var_reflection's flat boxes reflect everywhere in povray).
        if (hi_[axis] == lo_[axis]) {
            Vec3 n;
            n[axis] = 1;
            return n;
        }
        const double extent = std::fmax(hi_[axis] - lo_[axis], 1e-300);
        const double dLo = std::fabs(p[axis] - lo_[axis]) / extent;
        const double dHi = std::fabs(p[axis] - hi_[axis]) / extent;
        if (dLo < bestDist) {
            bestDist = dLo;
            bestAxis = axis;
            sign = -1;
        }
        if (dHi < bestDist) {
            bestDist = dHi;
            bestAxis = axis;
            sign = 1;
        }
    }
    Vec3 n;
    n[bestAxis] = sign;
    return n;
}

// povray 3.7's box uv (measured): the six faces unfolded into a cross on
// a 4 x 3 grid, each face a quarter of the width and a third of the
// height: -x, +z, +x, -z along the middle row (v 1/3..2/3), -y below and
// +y above the +z face.
bool Box::uv(const Vec3& p, double& u, double& v) const {
    const Vec3 size = hi_ - lo_;
    auto frac = [&](int axis) {
        return size[axis] > 0 ? std::clamp((p[axis] - lo_[axis]) / size[axis], 0.0, 1.0) : 0.0;
    };
    const double X = frac(0), Y = frac(1), Z = frac(2);
    const Vec3 n = normal(p);
    if (n.x < 0) {
        u = Z / 4;
        v = (1 + Y) / 3;
    } else if (n.x > 0) {
        u = 0.75 - Z / 4;
        v = (1 + Y) / 3;
    } else if (n.z > 0) {
        u = 0.25 + X / 4;
        v = (1 + Y) / 3;
    } else if (n.z < 0) {
        u = 1 - X / 4;
        v = (1 + Y) / 3;
    } else if (n.y < 0) {
        u = 0.25 + X / 4;
        v = Z / 3;
    } else {
        u = 0.25 + X / 4;
        v = 1 - Z / 3;
    }
    return true;
}

bool Box::inside(const Vec3& p) const {
    // Faces count as inside (povray: intersecting two boxes that share a
    // face leaves that face visible).
    return p.x >= lo_.x && p.x <= hi_.x && p.y >= lo_.y && p.y <= hi_.y && p.z >= lo_.z &&
           p.z <= hi_.z;
}

}  // namespace frameray::scene
