#include "scene/ray.h"

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

}  // namespace frameray::scene
