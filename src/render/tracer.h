// POV-Ray's classic shading model for one ray: ambient, diffuse with
// brilliance, phong and specular highlights, hard shadows from point lights.
#pragma once

#include "render/world.h"
#include "util/color.h"

namespace frameray::render {

// Per-thread counters, summed per frame for the statistics.
struct RayCounts {
    uint64_t camera = 0;
    uint64_t shadow = 0;

    RayCounts& operator+=(const RayCounts& o) {
        camera += o.camera;
        shadow += o.shadow;
        return *this;
    }
};

class Tracer {
public:
    explicit Tracer(const World& world) : world_(world), scene_(world.scene()) {}

    // Colour seen along a camera ray (working colour space, unclipped).
    RGB traceCamera(const scene::Ray& ray, RayCounts& counts) const;

private:
    RGB shade(const scene::Ray& ray, const Hit& hit, RayCounts& counts) const;

    const World& world_;
    const scene::Scene& scene_;
};

}  // namespace frameray::render
