// POV-Ray 3.7's radiosity settings (`global_settings { radiosity { } }`),
// with povray 3.7's defaults. render/radiosity.h uses them; their meaning
// is described there and in the README.
#pragma once

#include <string>

namespace frameray::scene {

struct RadiositySettings {
    // Rays per new sample, and the size of the pool of directions they are
    // taken from (the second value of `count`).
    int count = 35;
    int directionPool = 1600;
    // Most samples blended at a point, and (the second value) the fewest a
    // pretrace pass wants before it stops refining (0: no adaptive stop).
    int nearestCount = 5;
    int nearestCountPretrace = 0;
    double errorBound = 1.8;
    double lowErrorFactor = 0.5;  // error_bound is multiplied by this while pretracing
    int recursionLimit = 2;
    double pretraceStart =
        0.08;                   // mosaic block size of the first pretrace pass, of the image width
    double pretraceEnd = 0.04;  // ... of the last
    double minimumReuse = 0.015;  // reuse radius bounds, as fractions of the distance from the eye
    double maximumReuse = 0.2;
    double grayThreshold = 0.0;  // how much gathered light is turned grey
    double brightness = 1.0;
    double adcBailout = 0.01;
    bool alwaysSample = false;  // new samples in the final pass
    double maxSample = -1.0;    // brightest a gathered ray may be; <= 0: no limit
    bool normal = false;        // gather with the perturbed normal
    bool media = false;         // radiosity rays see media
    bool subsurface = false;
};

}  // namespace frameray::scene
