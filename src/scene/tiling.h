// The tiling pattern (povray 3.7's `tiling N`): tiles in the xz plane, each
// shaded from 0 at its centre to 1 at its edges, the value band split
// between the tilings' kinds of tile (measured from povray's renders).
// Only the three regular tilings are implemented: 1 squares, 2 hexagons, 3
// triangles; the parser refuses the others.
#pragma once

#include "util/vec3.h"

namespace frameray::scene {

// Whether `tiling n` is implemented.
bool tilingSupported(int n);

// The pattern value of tiling n (a supported one) at pattern-space point p.
double tilingValue(int n, const Vec3& p);

}  // namespace frameray::scene
