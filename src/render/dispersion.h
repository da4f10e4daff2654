// povray 3.7's dispersion (interior { dispersion D dispersion_samples N }):
// a ray refracting into or out of a dispersive interior splits into N
// monochrome rays, one per equal band of the visible spectrum, each bent
// by its own ior and weighted by its band's colour; the split rays stay
// monochrome through every later surface.
#pragma once

#include "scene/interior.h"
#include "util/color.h"

namespace frameray::render {

// Where in the spectrum a monochrome ray lies: 0 at the violet end, 1 at
// the red; negative for a white (unsplit) ray.
struct SpectralBand {
    double position = -1.0;
    bool white() const { return position < 0; }
};

// The centre of band k of n.
inline SpectralBand dispersionBand(int k, int n) {
    return {(k + 0.5) / n};
}

// The colour band k of n carries: the spectrum's colour integrated over
// the band (measured from povray 3.7; the n bands together give
// <0.9938, 1, 0.9962>, as in povray).
RGB dispersionBandColour(int k, int n);

// The ior a ray of `band` sees in `interior`: ior * D^(0.5 - position)
// (measured: violet bends most, a 7-band split of ior 1.5 and D 1.1 gives
// 1.5 * 1.1^(3/7) down to 1.5 * 1.1^(-3/7)).
double dispersedIor(const scene::Interior& interior, SpectralBand band);

}  // namespace frameray::render
