// Participating media (POV-Ray 3.7's `media { }`): what fills a hollow
// object's interior, or the whole scene's open air, and how it is sampled.
//
// A media emits light, absorbs it and scatters the light of the light
// sources toward the viewer; each of the three is a colour scaled by the
// media's density at the point (the product of its `density { }` blocks,
// each a pigment-like pattern whose colour is the density per channel).
// How the renderer integrates it along a ray is render/media.
#pragma once

#include <memory>
#include <vector>

#include "scene/texture.h"
#include "util/color.h"
#include "util/matrix.h"
#include "util/vec3.h"

namespace frameray::scene {

// scattering { TYPE, ... }: the phase functions of POV-Ray 3.7.
enum class ScatteringType {
    None = 0,
    Isotropic = 1,
    MieHazy = 2,
    MieMurky = 3,
    Rayleigh = 4,
    HenyeyGreenstein = 5,
};

struct Media {
    // Sampling (povray 3.7 defaults, measured: method 3, one interval,
    // samples 10, aa_level 3, aa_threshold 0.1, no jitter).
    int method = 3;
    int intervals = 1;
    int samplesMin = 10;
    int samplesMax = 10;
    double confidence = 0.9;
    double variance = 1.0 / 128.0;
    double ratio = 0.9;
    int aaLevel = 3;
    double aaThreshold = 0.1;
    double jitter = 0.0;
    // Methods 1 and 2: after k samples an interval whose sample variance
    // (per channel, of the mean) reaches sampleThreshold[k - 1] gets another
    // one, up to samplesMax + 1 (povray 3.7's confidence test; see
    // prepareSampling). Empty until prepareSampling runs.
    std::vector<double> sampleThreshold;

    RGB absorption{0.0};
    RGB emission{0.0};
    RGB scattering{0.0};
    ScatteringType scatteringType = ScatteringType::None;
    double eccentricity = 0.0;  // Henyey-Greenstein's g (povray default 0, measured)
    double extinction = 1.0;    // how much scattering takes from the light passing

    // Multiplied together; none = density 1 everywhere.
    std::vector<std::shared_ptr<const Pigment>> densities;

    // The density (per channel) at a point in the media's space, which is
    // the world for atmospheric media and follows the object otherwise.
    RGB densityAt(const Vec3& p) const;
    // Constant media (no density) are sampled over one interval whatever
    // `intervals` says (measured).
    bool constant() const { return densities.empty(); }
    bool scatters() const {
        return scatteringType != ScatteringType::None && !scattering.isBlack();
    }
    // The phase function for the cosine between the light's direction of
    // travel and the direction toward the viewer; isotropic is 1.
    double phase(double cosAngle) const;

    void transformBy(const Transform& t);
    // Fills sampleThreshold from samplesMax, confidence and variance: with
    // q(n) the chi-square value that n degrees of freedom exceed with
    // probability `confidence`, threshold[k - 1] = variance * q(k) /
    // q(samplesMax - 1) (variance * 1e-10 when q(samplesMax - 1) is 0);
    // a single threshold of 0 when samplesMax is 1. Called once the media's
    // block is read.
    void prepareSampling();
};

using MediaList = std::vector<std::shared_ptr<const Media>>;

// A density block's pigment before its items: density 1 everywhere; a
// pattern without a colour map takes its pigment default map (black to
// white for most).
Pigment defaultDensity();

}  // namespace frameray::scene
