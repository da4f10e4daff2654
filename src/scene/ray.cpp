#include "scene/ray.h"

#include <algorithm>
#include <cmath>

namespace frameray::scene {

bool Bounds::isFinite() const {
    return std::isfinite(lo.x) && std::isfinite(lo.y) && std::isfinite(lo.z) &&
           std::isfinite(hi.x) && std::isfinite(hi.y) && std::isfinite(hi.z);
}

Bounds Bounds::transformed(const Transform& t) const {
    if (isEmpty()) return {};
    if (t.isIdentity()) return *this;
    if (!isFinite()) return infinite();
    Bounds out;
    for (int i = 0; i < 8; ++i)
        out.extend(t.point({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z}));
    return out;
}

Bounds Bounds::transformedAxiswise(const Transform& t) const {
    if (isEmpty()) return {};
    const Matrix4& m = t.matrix();
    Bounds out;
    for (int k = 0; k < 3; ++k) {
        double lo_k = m.m[3][static_cast<size_t>(k)], hi_k = lo_k;
        for (int j = 0; j < 3; ++j) {
            const double c = m.m[static_cast<size_t>(j)][static_cast<size_t>(k)];
            if (c == 0) continue;  // 0 * infinity contributes nothing
            const double a = c * lo[j], b = c * hi[j];
            lo_k += std::min(a, b);
            hi_k += std::max(a, b);
        }
        out.lo[k] = lo_k;
        out.hi[k] = hi_k;
    }
    return out;
}

bool Bounds::clip(const Ray& ray, double& tMin, double& tMax) const {
    if (isEmpty()) return false;
    for (int axis = 0; axis < 3; ++axis) {
        const double l = lo[axis], h = hi[axis];
        if (l == -kInfinity && h == kInfinity) continue;
        const double o = ray.origin[axis], d = ray.direction[axis];
        if (d == 0) {
            if (o < l || o > h) return false;
            continue;
        }
        double t0 = (l - o) / d, t1 = (h - o) / d;
        if (t0 > t1) std::swap(t0, t1);
        tMin = std::max(tMin, t0);
        tMax = std::min(tMax, t1);
        if (tMin > tMax) return false;
    }
    return true;
}

Bounds Bounds::padded() const {
    if (isEmpty()) return *this;
    Bounds out = *this;
    for (int axis = 0; axis < 3; ++axis) {
        if (!std::isfinite(lo[axis]) || !std::isfinite(hi[axis])) continue;
        const double pad = (hi[axis] - lo[axis]) * 1e-9 +
                           (std::fabs(lo[axis]) + std::fabs(hi[axis])) * 1e-12 + 1e-300;
        out.lo[axis] -= pad;
        out.hi[axis] += pad;
    }
    return out;
}

}  // namespace frameray::scene
