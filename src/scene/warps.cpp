#include "scene/warps.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "util/lattice_hash.h"

namespace frameray::scene {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// The angle of (x, z) about the y axis in turns from +x towards +z, in
// [0, 1); len is hypot(x, z) and not zero.
double turnsAboutY(double x, double z, double len) {
    if (z == 0) return x > 0 ? 0.0 : 0.5;
    const double theta = std::acos(std::clamp(x / len, -1.0, 1.0));
    return (z < 0 ? kTwoPi - theta : theta) / kTwoPi;
}

// The mapping warps compute their coordinates for the default orientation
// (z) and then multiply them by this matrix built from the unit orientation
// o. It is not a rotation (povray's, measured by fitting its warped points
// for several orientations: exact to 1e-7); for z it is the identity and for
// x and y a quarter turn, and for -z it negates the point.
Vec3 orient(const Vec3& v, const Vec3& o) {
    return {(o.y + o.z) * v.x + o.x * v.z, (o.x + o.z) * v.y - o.y * v.z,
            -o.x * v.x + o.y * v.y + o.z * v.z};
}

// dist^e, where an exponent of 0 leaves the angles alone.
double distScale(double dist, double e) {
    return e == 0 ? 1.0 : std::pow(dist, e);
}

// povray's table of warp random numbers: the first 32768 outputs of the
// default-seeded 32-bit Mersenne Twister, each divided by 2^32 (measured:
// black_hole repeat + turbulence places the holes as povray 3.7 does).
const std::vector<double>& warpRandoms() {
    static const std::vector<double> table = [] {
        std::mt19937 engine;
        std::vector<double> t(32768);
        for (double& v : t) v = static_cast<double>(engine()) / 4294967296.0;
        return t;
    }();
    return table;
}

// The centre of the black hole whose repeat cell holds p.
Vec3 blackHoleCenter(const Warp& w, const Vec3& p) {
    if (!w.repeats) return w.center;
    int block[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i)
        if (w.repeat[i] >= 1e-10) block[i] = latticeFloor(p[i] / w.repeat[i]);
    Vec3 c = w.center;
    if (w.jittered) {
        const std::vector<double>& r = warpRandoms();
        const auto seed = static_cast<std::size_t>(latticeHash3(block[0], block[1], block[2]));
        for (int i = 0; i < 3; ++i) c[i] += r[(seed + i) % r.size()] * w.jitter[i];
    }
    for (int i = 0; i < 3; ++i) c[i] += w.repeat[i] * block[i];
    return c;
}

}  // namespace

Vec3 Warp::apply(const Vec3& p) const {
    switch (kind) {
        case Kind::Transform:
            return transform.inversePoint(p);
        case Kind::Turbulence:
            return p + mul(vectorTurbulence(p, turb), turb.amount);
        case Kind::Repeat: {
            Vec3 q = p;
            const double block = std::floor(q[axis] / width);
            q[axis] -= block * width;
            if (static_cast<long long>(block) & 1) {
                // Mirror: flipped axes change sign, the repeat axis within
                // its cell (measured: width - t).
                for (int i = 0; i < 3; ++i)
                    if (flip[i]) q[i] = -q[i];
                if (flip[axis]) q[axis] += width;
            }
            return q + offset * block;
        }
        case Kind::BlackHole: {
            const Vec3 d = p - blackHoleCenter(*this, p);
            const double r = length(d);
            if (r >= radius) return p;
            const double k = std::min(1.0, std::pow((radius - r) / radius, falloff) * strength);
            return inverse ? p - d * k : p + d * k;
        }
        // Measured against povray 3.7's pattern functions: the angle about y
        // becomes x, the height stays y (cylindrical) or becomes the
        // elevation (spherical) or the angle round the tube (toroidal), and z
        // takes the distance; dist_exp scales the angles by distance^e. A
        // point on the axis (or, spherical, at the origin) stays where it is.
        case Kind::Cylindrical: {
            const double len = std::hypot(p.x, p.z);
            if (len == 0) return p;
            const double theta = turnsAboutY(p.x, p.z, len);
            return orient({theta * distScale(len, distExp), p.y, len}, orientation);
        }
        case Kind::Spherical: {
            const double r = length(p);
            if (r == 0) return p;
            const double len = std::hypot(p.x, p.z);
            const double theta = len == 0 ? 0.0 : turnsAboutY(p.x, p.z, len);
            const double phi = 0.5 + std::asin(std::clamp(p.y / r, -1.0, 1.0)) / std::numbers::pi;
            const double s = distScale(r, distExp);
            return orient({theta * s, phi * s, r}, orientation);
        }
        case Kind::Toroidal: {
            const double len = std::hypot(p.x, p.z);
            if (len == 0) return p;
            const double theta = turnsAboutY(p.x, p.z, len);
            // Round the tube: 0 on the inside of the ring, a half on the
            // outside, rising through the top. On the ring's centre line
            // povray's angle is NaN; 0 is taken there.
            const double d = len - majorRadius;
            const double dist = std::hypot(d, p.y);
            double phi = 0;
            if (dist > 0) {
                phi = std::acos(std::clamp(-d / dist, -1.0, 1.0)) / kTwoPi;
                if (p.y > 0) phi = 1.0 - phi;
            }
            const double s = distScale(dist, distExp);
            return orient({theta * s, phi * s, dist}, orientation);
        }
        case Kind::Planar:
            // z is replaced by the plane's distance before orienting.
            return orient({p.x, p.y, planeDistance}, orientation);
    }
    return p;
}

}  // namespace frameray::scene
