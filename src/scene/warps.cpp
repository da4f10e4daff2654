#include "scene/warps.h"

#include <algorithm>
#include <cmath>
#include <numbers>

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
            const Vec3 d = p - center;
            const double r = length(d);
            if (r >= radius) return p;
            const double k = strength * std::pow(1.0 - r / radius, falloff);
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
