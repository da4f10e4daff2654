// The tiling and pavement patterns (povray 3.7's `tiling N`): tiles in the xz plane, each
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

// pavement: tiles made of number_of_tiles triangles, squares or hexagons
// of unit side, shaded from 1 on their edges to 0 inside. Only single
// tiles are implemented (number_of_tiles 1, pattern 1); `exterior` shapes
// the squares' corners (0 sharp, 1 cut, 2 round), `interior` and `form`
// only matter between the cells of a multi-cell tile.
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
