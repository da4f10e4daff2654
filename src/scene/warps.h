// Pattern warps (seed 000 "warp"): point-to-point maps applied before a
// pattern is evaluated. A pattern's transformations and warps form one chain
// in the order written; povray evaluates it from the last item to the first
// (a transformation written after a warp acts before it), which Pattern
// reproduces by walking its chain backwards.
#pragma once

#include "scene/noise.h"
#include "util/matrix.h"
#include "util/vec3.h"

namespace frameray::scene {

struct Warp {
    enum class Kind {
        Transform,
        Turbulence,
        Repeat,
        BlackHole,
        // The mapping warps: space wrapped onto a cylinder, sphere, torus or
        // plane (see warps.cpp for the coordinates each one yields).
        Cylindrical,
        Spherical,
        Toroidal,
        Planar
    };
    Kind kind = Kind::Transform;

    // Transform: the pattern's transformation; points go through its inverse.
    Transform transform;
    // Turbulence: displacement by vector turbulence times turb.amount.
    Turbulence turb;
    // Repeat: the space between 0 and width along `axis` repeats; every
    // repetition moves by `offset`, odd ones mirror the axes in `flip`.
    int axis = 0;
    double width = 1;
    Vec3 offset{0, 0, 0};
    bool flip[3] = {false, false, false};
    // BlackHole: within `radius` of `center` points move away from it by
    // (p - center) * strength * (1 - r / radius)^falloff, towards it when
    // inverse (measured from povray's pattern functions).
    // The strength is capped at 1 (a point never moves past the centre).
    // `repeat` (components below 1e-10 do not repeat) puts a hole in every
    // cell of that lattice, the cell's hole moved by `jitter` times povray's
    // random numbers for the cell.
    Vec3 center{0, 0, 0};
    double radius = 1, strength = 1, falloff = 2;
    bool inverse = false;
    Vec3 repeat{0, 0, 0}, jitter{0, 0, 0};
    bool repeats = false, jittered = false;
    // Mapping warps: the unit orientation (default z), dist_exp (0: the
    // angles are not scaled by the distance), toroidal's major_radius and
    // planar's distance.
    Vec3 orientation{0, 0, 1};
    double distExp = 0, majorRadius = 1, planeDistance = 0;

    static Warp makeTransform(const Transform& t) {
        Warp w;
        w.transform = t;
        return w;
    }
    Vec3 apply(const Vec3& p) const;
};

}  // namespace frameray::scene
