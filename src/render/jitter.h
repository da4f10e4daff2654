// Sub-pixel jitter for anti-aliasing: a fixed offset per sample position.
//
// POV-Ray 3.7 jitters anti-aliasing samples by an offset that is a pure
// function of the sample's image-plane position (hashed through the lattice
// permutation into a table of 256 well-spread offsets). The same position
// always gets the same offset, so a still scene renders identically every
// frame of an animation (no flicker) and whatever the thread count. We use
// the same function so that our anti-aliased pixels match povray's.
#pragma once

namespace frameray::render {

struct JitterOffset {
    double x = 0, y = 0;  // each in [-0.5, 0.5]
};

// The offset POV-Ray applies at image-plane position (x, y), in pixels
// before scaling by the jitter amount.
JitterOffset jitterAt(double x, double y);

}  // namespace frameray::render
