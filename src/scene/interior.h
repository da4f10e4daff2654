// What fills an object (seed 003 §5.4.3.4 and the 3.7 interior block): the
// index of refraction, dispersion, and the fading of light travelling
// through it. Objects that share one Interior (the children of a CSG that
// inherited it) form one region: a ray inside one of them is inside all.
#pragma once

#include "scene/media.h"
#include "util/color.h"

namespace frameray::scene {

struct Interior {
    double ior = 1.0;
    double dispersion = 1.0;  // ratio of violet to red ior; 1 = none
    int dispersionSamples = 7;
    // Light crossing a distance d inside fades toward fadeColor: by
    // 1 / (1 + (d / fadeDistance)^fadePower), or exp(-d / fadeDistance)
    // for fadePower >= 1000 (per channel exp(-d / fadeDistance * (1 -
    // fadeColor))). fadeDistance 0 = no fading.
    double fadeDistance = 0.0;
    double fadePower = 0.0;
    RGB fadeColor{0.0};
    double caustics = 0.0;  // povray's fake caustics (render/optics.h, fakeCaustics)
    // media { } blocks, in the object's space. povray 3.7 samples them
    // only inside hollow objects (measured: a non-hollow container shows
    // no media and casts no media shadow).
    MediaList media;

    // povray fades whenever fade_distance > 0, even at the default power 0
    // (measured: 1 / (1 + (d / fade_distance)^0) = 0.5 of the light passes).
    bool fades() const { return fadeDistance > 0; }
};

}  // namespace frameray::scene
