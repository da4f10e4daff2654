#include "scene/tiling.h"

#include <algorithm>
#include <cmath>

namespace frameray::scene {

namespace {

constexpr double kSqrt3 = 1.7320508075688772;

// Tiling 1: unit squares with edges on whole x and z; 1 - (distance to the
// nearest edge) / 0.5.
double squares(const Vec3& p) {
    const double fx = p.x - std::floor(p.x), fz = p.z - std::floor(p.z);
    const double d = std::min({fx, 1.0 - fx, fz, 1.0 - fz});
    return 1.0 - 2.0 * d;
}

// Tiling 2: hexagons of unit side with corners on the x axis, centred at
// (-1, 0) + i (1.5, sqrt3/2) + j (0, sqrt3) (the origin is a corner); the
// hexagonal distance from the centre, 1 on the edges.
double hexagons(const Vec3& p) {
    const double x = p.x + 1.0, z = p.z;
    // Axial coordinates of the lattice, rounded to the nearest centre.
    const double q = x * (2.0 / 3.0);
    const double r = z / kSqrt3 - x / 3.0;
    const double s = -q - r;
    double rq = std::round(q), rr = std::round(r);
    const double rs = std::round(s);
    const double dq = std::abs(rq - q), dr = std::abs(rr - r), ds = std::abs(rs - s);
    if (dq > dr && dq > ds)
        rq = -rr - rs;
    else if (dr > ds)
        rr = -rq - rs;
    const double dx = x - 1.5 * rq;
    const double dz = z - (kSqrt3 / 2.0) * rq - kSqrt3 * rr;
    const double c = kSqrt3 / 2.0;
    const double m =
        std::max({std::abs(dz), std::abs(c * dx + 0.5 * dz), std::abs(c * dx - 0.5 * dz)});
    return m / c;
}

// Tiling 3: equilateral triangles of unit side, corners at i + j/2 along x
// and j sqrt3/2 along z. Triangles pointing +z take 0 to 0.5, those
// pointing -z 0.5 to 1, each rising from its centre: half of 1 - (distance
// to the nearest edge) / inradius.
double triangles(const Vec3& p) {
    const double u = p.x - p.z / kSqrt3, v = p.z * 2.0 / kSqrt3;
    const double fu = u - std::floor(u), fv = v - std::floor(v);
    const bool up = fu + fv < 1.0;
    // Distances to the edges in units of the triangle's height.
    const double m =
        up ? std::min({fu, fv, 1.0 - fu - fv}) : std::min({1.0 - fu, 1.0 - fv, fu + fv - 1.0});
    const double shade = 1.0 - 3.0 * m;
    return up ? 0.5 * shade : 0.5 + 0.5 * shade;
}

}  // namespace

bool tilingSupported(int n) {
    return n >= 1 && n <= 3;
}

double tilingValue(int n, const Vec3& p) {
    switch (n) {
        case 1:
            return squares(p);
        case 2:
            return hexagons(p);
        case 3:
            return triangles(p);
        default:
            return 0.0;
    }
}

}  // namespace frameray::scene
