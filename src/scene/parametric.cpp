#include "scene/parametric.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "scene/implicit_search.h"
#include "scene/shape_math.h"

namespace frameray::scene {

namespace {

// A rectangle of (u, v) and the ray's interval through its box.
struct Sector {
    double u0, u1, v0, v1;
    double tNear;
};

// Deep enough for accuracy 1e-12 over a range of 1e3; deeper sectors are
// treated as leaves.
constexpr int kMaxDepth = 56;
// Pending sectors: at most three siblings wait per level.
constexpr int kStackSize = 4 * kMaxDepth + 4;

bool inRange(double x, double lo, double hi, double margin) {
    return x >= lo - margin && x <= hi + margin;
}

}  // namespace

Parametric::Parametric(ParametricSettings settings) : s_(std::move(settings)) {
    const Bounds b = bounds();
    scale_ = std::max(1e-300, length(b.hi - b.lo));
}

bool Parametric::containerInterval(const Ray& ray, double& t0, double& t1) const {
    if (s_.sphereContainer)
        return detail::distanceRoots(ray.origin - s_.center, ray.direction, s_.radius * s_.radius,
                                     t0, t1);
    return detail::clipToBox(ray, s_.boxLo, s_.boxHi, t0, t1);
}

Bounds Parametric::bounds() const {
    if (s_.sphereContainer) return {s_.center - Vec3(s_.radius), s_.center + Vec3(s_.radius)};
    return {s_.boxLo, s_.boxHi};
}

void Parametric::derivatives(double u, double v, Vec3& pu, Vec3& pv) const {
    const double hu = 1e-6 * std::max(1.0, std::fabs(u));
    const double hv = 1e-6 * std::max(1.0, std::fabs(v));
    pu = (point(u + hu, v) - point(u - hu, v)) / (2 * hu);
    pv = (point(u, v + hv) - point(u, v - hv)) / (2 * hv);
}

void Parametric::allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const {
    // povray reports one crossing per ray, the first (see the header).
    double t;
    if (firstHit(ray, tMin, tMax, t)) ts.push_back(t);
}

bool Parametric::firstHit(const Ray& ray, double tMin, double tMax, double& tHit) const {
    double c0, c1;
    if (!containerInterval(ray, c0, c1)) return false;
    const double speed = length(ray.direction);
    if (!(speed > 0)) return false;
    // A ray leaving the surface (shadows, reflections) must not find its
    // own start again.
    const double lo = std::max(c0, tMin + 1e-9 * scale_ / speed);
    double best = std::min(c1, tMax);
    if (!(lo < best)) return false;

    const double grow = s_.maxGradient;
    // The ray's interval through the box of a sector, within [lo, best].
    auto interval = [&](const Sector& s, double& near, double& far) {
        const double hu = 0.5 * (s.u1 - s.u0), hv = 0.5 * (s.v1 - s.v0);
        const Vec3 c = point(s.u0 + hu, s.v0 + hv);
        const double r = grow * (hu + hv) + 1e-12 * scale_;
        near = lo;
        far = best;
        for (int a = 0; a < 3; ++a) {
            const double o = ray.origin[a], d = ray.direction[a];
            if (d == 0) {
                if (o < c[a] - r || o > c[a] + r) return false;
                continue;
            }
            double ta = (c[a] - r - o) / d, tb = (c[a] + r - o) / d;
            if (ta > tb) std::swap(ta, tb);
            near = std::max(near, ta);
            far = std::min(far, tb);
            if (near > far) return false;
        }
        return true;
    };

    // Newton's method on point(u, v) = origin + t direction, from the
    // middle of a leaf sector; the root counts when it lies in (or next
    // to) that sector, inside the rectangle, and nearer than `best`.
    auto solve = [&](const Sector& s) {
        const double du = s.u1 - s.u0, dv = s.v1 - s.v0;
        double u = s.u0 + 0.5 * du, v = s.v0 + 0.5 * dv;
        const Vec3 c = point(u, v);
        double t = dot(c - ray.origin, ray.direction) / (speed * speed);
        const double tolerance = 1e-10 * scale_;
        bool converged = false;
        for (int i = 0; i < 24; ++i) {
            const Vec3 f = point(u, v) - ray.at(t);
            Vec3 pu, pv;
            derivatives(u, v, pu, pv);
            const Vec3 nd = -ray.direction;
            const Vec3 bxc = cross(pv, nd);
            const double det = dot(pu, bxc);
            if (!(std::fabs(det) > 0) || !std::isfinite(det)) return false;
            const double stepU = -dot(f, bxc) / det;
            const double stepV = -dot(pu, cross(f, nd)) / det;
            const double stepT = -dot(pu, cross(pv, f)) / det;
            u += stepU;
            v += stepV;
            t += stepT;
            if (!std::isfinite(u + v + t)) return false;
            // Far outside its sector: the root (if any) belongs to another.
            if (!inRange(u, s.u0, s.u1, 4 * du + 1e-9) || !inRange(v, s.v0, s.v1, 4 * dv + 1e-9))
                return false;
            if (std::fabs(stepU) <= 1e-13 * std::max(1.0, std::fabs(u)) &&
                std::fabs(stepV) <= 1e-13 * std::max(1.0, std::fabs(v))) {
                converged = true;
                break;
            }
        }
        const double residual = length(point(u, v) - ray.at(t));
        if (!converged && !(residual <= tolerance)) return false;
        if (!(residual <= 1e-7 * scale_)) return false;
        const double eu = 1e-9 * std::max(1.0, std::fabs(s_.uMax - s_.uMin));
        const double ev = 1e-9 * std::max(1.0, std::fabs(s_.vMax - s_.vMin));
        if (!inRange(u, s.u0, s.u1, du + eu) || !inRange(v, s.v0, s.v1, dv + ev)) return false;
        if (!inRange(u, s_.uMin, s_.uMax, eu) || !inRange(v, s_.vMin, s_.vMax, ev)) return false;
        if (!(t > lo && t < best)) return false;
        best = t;
        return true;
    };

    std::array<Sector, kStackSize> stack;
    std::array<int, kStackSize> depth;
    int top = 0;
    bool found = false;
    {
        Sector root{s_.uMin, s_.uMax, s_.vMin, s_.vMax, 0};
        double far;
        if (!interval(root, root.tNear, far)) return false;
        stack[0] = root;
        depth[0] = 0;
        top = 1;
    }
    const double acc = s_.accuracy;
    while (top > 0) {
        --top;
        const Sector s = stack[top];
        const int level = depth[top];
        if (s.tNear >= best) continue;
        const bool splitU = s.u1 - s.u0 > acc, splitV = s.v1 - s.v0 > acc;
        if ((!splitU && !splitV) || level >= kMaxDepth) {
            if (solve(s)) found = true;
            continue;
        }
        // The children whose boxes the ray crosses, nearest popped first.
        std::array<Sector, 4> kids;
        int n = 0;
        const double um = 0.5 * (s.u0 + s.u1), vm = 0.5 * (s.v0 + s.v1);
        for (int i = 0; i < (splitU ? 2 : 1); ++i) {
            for (int j = 0; j < (splitV ? 2 : 1); ++j) {
                Sector k{s.u0, s.u1, s.v0, s.v1, 0};
                if (splitU) (i == 0 ? k.u1 : k.u0) = um;
                if (splitV) (j == 0 ? k.v1 : k.v0) = vm;
                double far;
                if (interval(k, k.tNear, far)) kids[n++] = k;
            }
        }
        // Insertion sort, farthest first (at most four).
        for (int i = 1; i < n; ++i)
            for (int j = i; j > 0 && kids[j - 1].tNear < kids[j].tNear; --j)
                std::swap(kids[j - 1], kids[j]);
        for (int i = 0; i < n && top < kStackSize; ++i) {
            stack[top] = kids[i];
            depth[top] = level + 1;
            ++top;
        }
    }
    if (found) tHit = best;
    return found;
}

bool Parametric::parametersOf(const Vec3& p, double& uOut, double& vOut) const {
    const double acc = s_.accuracy;
    double bestResidual = kInfinity;
    // Gauss-Newton on |point(u, v) - p| from the middle of a leaf sector.
    auto settle = [&](const Sector& s) {
        double u = 0.5 * (s.u0 + s.u1), v = 0.5 * (s.v0 + s.v1);
        for (int i = 0; i < 16; ++i) {
            const Vec3 f = point(u, v) - p;
            Vec3 pu, pv;
            derivatives(u, v, pu, pv);
            const double a = dot(pu, pu), b = dot(pu, pv), c = dot(pv, pv);
            const double det = a * c - b * b;
            if (!(det > 0)) break;
            const double gu = dot(pu, f), gv = dot(pv, f);
            const double stepU = -(c * gu - b * gv) / det;
            const double stepV = -(a * gv - b * gu) / det;
            u = std::clamp(u + stepU, s_.uMin, s_.uMax);
            v = std::clamp(v + stepV, s_.vMin, s_.vMax);
            if (std::fabs(stepU) + std::fabs(stepV) <= 1e-14 * (1 + std::fabs(u) + std::fabs(v)))
                break;
        }
        const double residual = length(point(u, v) - p);
        if (residual < bestResidual) {
            bestResidual = residual;
            uOut = u;
            vOut = v;
        }
        return residual <= 1e-8 * scale_;
    };
    auto contains = [&](const Sector& s) {
        const double hu = 0.5 * (s.u1 - s.u0), hv = 0.5 * (s.v1 - s.v0);
        const Vec3 c = point(s.u0 + hu, s.v0 + hv);
        const double r = s_.maxGradient * (hu + hv) + 1e-7 * scale_;
        return std::fabs(p.x - c.x) <= r && std::fabs(p.y - c.y) <= r && std::fabs(p.z - c.z) <= r;
    };

    std::array<Sector, kStackSize> stack;
    std::array<int, kStackSize> depth;
    stack[0] = {s_.uMin, s_.uMax, s_.vMin, s_.vMax, 0};
    depth[0] = 0;
    int top = 1;
    while (top > 0) {
        --top;
        const Sector s = stack[top];
        const int level = depth[top];
        const bool splitU = s.u1 - s.u0 > acc, splitV = s.v1 - s.v0 > acc;
        if ((!splitU && !splitV) || level >= kMaxDepth) {
            if (settle(s)) return true;
            continue;
        }
        const double um = 0.5 * (s.u0 + s.u1), vm = 0.5 * (s.v0 + s.v1);
        for (int i = 0; i < (splitU ? 2 : 1); ++i) {
            for (int j = 0; j < (splitV ? 2 : 1); ++j) {
                Sector k{s.u0, s.u1, s.v0, s.v1, 0};
                if (splitU) (i == 0 ? k.u1 : k.u0) = um;
                if (splitV) (j == 0 ? k.v1 : k.v0) = vm;
                if (top < kStackSize && contains(k)) {
                    stack[top] = k;
                    depth[top] = level + 1;
                    ++top;
                }
            }
        }
    }
    return bestResidual < kInfinity;
}

Vec3 Parametric::normal(const Vec3& p) const {
    double u = 0.5 * (s_.uMin + s_.uMax), v = 0.5 * (s_.vMin + s_.vMax);
    parametersOf(p, u, v);
    Vec3 pu, pv;
    derivatives(u, v, pu, pv);
    Vec3 n = cross(pu, pv);
    // Where the surface pinches to a point (a sphere's pole) the
    // derivatives are parallel: take the normal a little way inside the
    // rectangle instead.
    if (!(length(n) > 1e-9 * length(pu) * length(pv)) || !(length(n) > 0)) {
        const double du = 1e-5 * (s_.uMax - s_.uMin), dv = 1e-5 * (s_.vMax - s_.vMin);
        const double u2 = u + du <= s_.uMax ? u + du : u - du;
        const double v2 = v + dv <= s_.vMax ? v + dv : v - dv;
        derivatives(u2, v2, pu, pv);
        n = cross(pu, pv);
    }
    const double len = length(n);
    if (!(len > 0) || !std::isfinite(len)) return Vec3(0, 1, 0);
    return n / len;
}

}  // namespace frameray::scene
