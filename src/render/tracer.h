// POV-Ray's classic shading model for one ray: ambient, diffuse with
// brilliance, phong and specular highlights, under the lights of
// render/lighting.h.
#pragma once

#include "render/atmosphere.h"
#include "render/lighting.h"
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
    // `quality` is +Q: shadows from 4, area lights from 5, rainbows and
    // fogs from 9 (POV-Ray).
    explicit Tracer(const World& world, int quality = 9)
        : world_(world),
          scene_(world.scene()),
          atmosphere_(world.scene(), quality >= 9),
          lighting_(LightingQuality::forQuality(quality)) {}

    // Colour seen along a camera ray (working colour space, unclipped).
    RGB traceCamera(const scene::Ray& ray, RayCounts& counts) const;

private:
    RGB shade(const scene::Ray& ray, const Hit& hit, RayCounts& counts) const;

    const World& world_;
    const scene::Scene& scene_;
    AtmosphereView atmosphere_;
    LightingQuality lighting_;
};

}  // namespace frameray::render
