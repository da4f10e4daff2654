// The tiling and pavement patterns (povray 3.7's `tiling N` and
// `pavement`): tiles in the xz plane. A tiling with K kinds of tile gives a
// tile of kind k the values k/K (inside) to (k+1)/K (on its edges): 1 - d/w
// clamped at 0, d the distance to the tile's nearest edge and w the
// tiling's shade width (mostly the inradius of its smallest tile). All
// geometry, kinds and widths were measured from povray's values (read
// through pigment_pattern); points exactly on an edge may pick another
// tile than povray. The five-fold tilings 25 to 27 are not implemented and
// the parser refuses them.
#pragma once

#include "util/vec3.h"

namespace frameray::scene {

// Whether `tiling n` is implemented.
bool tilingSupported(int n);

// The pattern value of tiling n (a supported one) at pattern-space point p.
double tilingValue(int n, const Vec3& p);

// pavement: tiles made of number_of_tiles triangles, squares or hexagons
// of unit side, shaded from 1 on their edges to 0 inside. Implemented:
// number_of_tiles 1 and 2 (pattern 1: lozenges, dominoes, hexagon pairs)
// and the straight square tromino (3, pattern 1);
// `exterior` shapes the squares' and dominoes' corners (0 sharp, 1 cut, 2
// round); `interior` and `form` change nothing in what is implemented
// except where the parser refuses them (measured).
struct PavementSettings {
    int sides = 3;
    int tiles = 1;
    int pattern = 1;
    int exterior = 0;
    int interior = 0;
    int form = 0;
};

double pavementValue(const PavementSettings& s, const Vec3& p);

}  // namespace frameray::scene
