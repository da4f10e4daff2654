// Rays and axis-aligned bounds, shared by shapes and the renderer.
#pragma once

#include <limits>

#include "util/matrix.h"
#include "util/vec3.h"

namespace frameray::scene {

// origin + t * direction. The direction need not be unit length: rays are
// carried into object space by the inverse transform without renormalising,
// so a hit's t means the same distance parameter in every space.
struct Ray {
    Vec3 origin;
    Vec3 direction;

    Vec3 at(double t) const { return origin + direction * t; }
};

constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Bounds {
    Vec3 lo{kInfinity, kInfinity, kInfinity};
    Vec3 hi{-kInfinity, -kInfinity, -kInfinity};

    static Bounds infinite() {
        return {{-kInfinity, -kInfinity, -kInfinity}, {kInfinity, kInfinity, kInfinity}};
    }
    bool isEmpty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    bool isFinite() const;
    void extend(const Vec3& p) {
        lo = vmin(lo, p);
        hi = vmax(hi, p);
    }
    void extend(const Bounds& b) {
        lo = vmin(lo, b.lo);
        hi = vmax(hi, b.hi);
    }
    // The common part; empty when the two do not overlap.
    Bounds intersected(const Bounds& b) const { return {vmax(lo, b.lo), vmin(hi, b.hi)}; }
    // Conservative bounds of this box's image under `t`: the box around
    // its eight transformed corners. Empty stays empty; a box that is
    // infinite along any axis becomes infinite along all of them.
    Bounds transformed(const Transform& t) const;
    // The same by interval arithmetic, axis by axis, so an extent stays
    // finite wherever only finite extents feed it (an infinite cylinder's
    // box keeps its two finite axes under scaling and translation). For
    // bounds refinement (csg.h); transformed() is what the BVH uses.
    Bounds transformedAxiswise(const Transform& t) const;
    // Narrows [tMin, tMax] to where the ray is inside the box; false when
    // that is empty (a slab test; infinite extents never narrow it).
    bool clip(const Ray& ray, double& tMin, double& tMax) const;
    // Grown by a relative margin, so rounding in clip() never rejects a
    // surface that touches the box.
    Bounds padded() const;
};

}  // namespace frameray::scene
