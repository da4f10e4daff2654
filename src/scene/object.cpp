#include "scene/object.h"

namespace frameray::scene {

Bounds Object::worldBounds() const {
    const Bounds b = shape->bounds();
    if (!b.isFinite()) return Bounds::infinite();
    Bounds out;
    for (int i = 0; i < 8; ++i) {
        const Vec3 corner{(i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y,
                          (i & 4) ? b.hi.z : b.lo.z};
        out.extend(transform.point(corner));
    }
    return out;
}

}  // namespace frameray::scene
