// POV-Ray's classic shading model for one ray: ambient, diffuse with
// brilliance, phong and specular highlights, hard shadows from point lights.
#pragma once

#include "render/atmosphere.h"
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
    // `volumetric`: rainbows and fogs are traced (POV-Ray: quality 9 and up).
    explicit Tracer(const World& world, bool volumetric = true)
        : world_(world), scene_(world.scene()), atmosphere_(world.scene(), volumetric) {}

    // Colour seen along a camera ray (working colour space, unclipped).
    RGB traceCamera(const scene::Ray& ray, RayCounts& counts) const;

private:
    RGB shade(const scene::Ray& ray, const Hit& hit, RayCounts& counts) const;

    const World& world_;
    const scene::Scene& scene_;
    AtmosphereView atmosphere_;
};

}  // namespace frameray::render
