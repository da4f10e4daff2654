// The crackle pattern (a cellular, Voronoi-style pattern): one feature
// point per unit cell, and a value from the distances to the nearest
// three of them. Matched to povray 3.7: its feature points come from a
// table measured from the binary (crackle_table.cpp), its value is
//   clamp(form.x·d1 + form.y·d2 + form.z·d3, 0, 1)
// with d_i = (|Δx|^m + |Δy|^m + |Δz|^m + |offset|^m)^(1/m) for metric m,
// and `solid` gives every cell the noise value at its feature point.
#pragma once

#include <array>

#include "scene/noise.h"
#include "util/vec3.h"

namespace frameray::scene {

inline constexpr int kCrackleTableSize = 4098;
extern const std::array<double, kCrackleTableSize> kCrackleTable;

struct CrackleSettings {
    Vec3 form{-1, 1, 0};
    double metric = 2;
    double offset = 0;
    bool solid = false;
};

// The raw crackle value at pattern-space point p.
double crackle(const Vec3& p, const CrackleSettings& settings, NoiseGenerator generator);

// The feature point of the unit cell whose low corner is (ix, iy, iz).
Vec3 crackleFeaturePoint(int ix, int iy, int iz);

// The cells pattern: one random value in [0, 1) per unit cube. povray takes
// it from the same table as crackle's feature points (measured: the value
// of cell c is the x offset of crackle's feature point in c), with the cube
// found after the block patterns' 1e-10 nudge.
double cellsValue(const Vec3& p);

}  // namespace frameray::scene
