#include "scene/warps.h"

#include <cmath>

namespace frameray::scene {

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
    }
    return p;
}

}  // namespace frameray::scene
