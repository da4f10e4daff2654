// Rays and axis-aligned bounds, shared by shapes and the renderer.
#pragma once

#include <limits>

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

    static Bounds infinite() { return {{-kInfinity, -kInfinity, -kInfinity}, {kInfinity, kInfinity, kInfinity}}; }
    bool isEmpty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    bool isFinite() const;
    void extend(const Vec3& p) { lo = vmin(lo, p); hi = vmax(hi, p); }
};

}  // namespace frameray::scene
