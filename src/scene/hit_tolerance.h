#pragma once

#include <algorithm>
#include <cmath>

#include "util/vec3.h"

namespace frameray::scene {

// How near a ray's origin a surface crossing may lie and still be seen.
//
// povray 3.7 (facts from its backend/render/trace.cpp, backend/scene/
// objects.cpp, backend/configbackend.h and backend/shape/blob.cpp) drops,
// along its unit-length rays:
//  - every crossing nearer than 1e-4 units, for every kind of ray (camera,
//    reflected, refracted, photon): kMinHitDepth;
//  - on a shadow ray, crossings nearer than 1e-3 to the lit point or to the
//    light, and, after a translucent surface, nearer than 1e-3 past it:
//    kShadowTolerance;
//  - blob crossings nearer than 1e-2: kBlobDepthTolerance (the other shapes'
//    own tolerances are at most 1e-4 along the world ray).
// Those distances are absolute: two surfaces 1e-8 apart (a liquid's skin
// just outside its glass) are one surface to povray whatever the scene's
// size, and frameray matches it.
//
// frameray also renders a scene scaled down by 1e-4 as it renders it at
// unit size (tests/stability). So where the coordinates involved are below
// 1 in magnitude, the tolerance shrinks with them: at unit size and above it
// is povray's distance exactly.
inline constexpr double kMinHitDepth = 1e-4;
inline constexpr double kShadowTolerance = 1e-3;
inline constexpr double kBlobDepthTolerance = 1e-2;

// The largest coordinate magnitude of a and b.
inline double coordinateMagnitude(const Vec3& a, const Vec3& b) {
    return std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z), std::fabs(b.x), std::fabs(b.y),
                     std::fabs(b.z)});
}

// `tolerance` (a povray distance) for coordinates of magnitude `magnitude`.
inline double scaledTolerance(double tolerance, double magnitude) {
    return tolerance * std::min(1.0, magnitude);
}

}  // namespace frameray::scene
