#include "scene/media.h"

#include <algorithm>
#include <cmath>

#include "util/chi_square.h"

namespace frameray::scene {

RGB Media::densityAt(const Vec3& p) const {
    RGB d(1.0);
    for (const auto& density : densities) {
        d *= density->at(p).rgb;
        if (d.isBlack()) break;
    }
    return d;
}

double Media::phase(double c) const {
    // Measured with povray 3.7 (a slab lit by one parallel light at angles
    // from 0 to 180 degrees, extinction 0): the Mie and Rayleigh shapes of
    // the literature, each with povray's own overall scale; Henyey-
    // Greenstein normalised to an average of 1 over the sphere.
    const double x = 0.5 * (1.0 + c);
    switch (scatteringType) {
        case ScatteringType::MieHazy: {
            const double x2 = x * x, x4 = x2 * x2;
            return 0.57665 * (1.0 + 9.0 * x4 * x4);
        }
        case ScatteringType::MieMurky: {
            double x32 = x;
            for (int i = 0; i < 5; ++i) x32 *= x32;
            return 0.49571 * (1.0 + 50.0 * x32);
        }
        case ScatteringType::Rayleigh:
            return 0.79935 * (1.0 + c * c);
        case ScatteringType::HenyeyGreenstein: {
            const double g = eccentricity;
            const double d = 1.0 + g * g - 2.0 * g * c;
            return d > 0 ? (1.0 - g * g) / (d * std::sqrt(d)) : 0.0;
        }
        default:
            return 1.0;
    }
}

void Media::transformBy(const Transform& t) {
    for (auto& density : densities) {
        auto moved = std::make_shared<Pigment>(*density);
        moved->transform(t);
        density = std::move(moved);
    }
}

void Media::prepareSampling() {
    sampleThreshold.assign(static_cast<size_t>(std::max(samplesMax, 1)), 0.0);
    if (samplesMax <= 1) return;
    double t = chiSquareUpperTailInverse(samplesMax - 1, confidence);
    t = t > 0.0 ? variance / t : variance * 1e-10;
    for (int i = 0; i < samplesMax; ++i)
        sampleThreshold[size_t(i)] = t * chiSquareUpperTailInverse(i + 1, confidence);
}

// A density pattern given without a colour map takes the same default map
// as in a pigment: black to white, or the pattern's own (bozo, marble,
// wood, agate, radial, mandel; measured: a `density { bozo }` box of
// absorbing media casts povray's red, green and blue bozo shadow).
Pigment defaultDensity() {
    return Pigment(Color(RGB(1.0)));
}

}  // namespace frameray::scene
