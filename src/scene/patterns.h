// Deterministic (noise-free) pigment patterns (seed 003 §5.4.1): colour-list
// patterns pick an index, colour-mapped patterns give a value in [0, 1]
// after the wave type, frequency and phase. Evaluation is const, thread-safe
// and allocation-free.
#pragma once

#include "util/vec3.h"

namespace frameray::scene {

enum class PatternKind {
    // colour-list patterns
    Checker, Hexagon, Brick,
    // colour-mapped patterns
    Gradient, Onion, Radial, Spherical, Cylindrical, Planar, Boxed, Leopard, Quilted, Spiral1, Spiral2,
};

enum class WaveType { Ramp, Triangle, Sine, Scallop, Cubic, Poly };

struct Pattern {
    PatternKind kind = PatternKind::Gradient;
    Vec3 gradient{1, 0, 0};       // gradient direction, normalised
    Vec3 brickSize{8, 3, 4.5};
    double mortar = 0.5;
    double control0 = 1, control1 = 1;  // quilted
    int arms = 0;                 // spiral1 / spiral2
    WaveType wave = WaveType::Ramp;
    double exponent = 1;          // poly_wave
    double frequency = 1, phase = 0;

    // Number of colours a colour-list pattern takes (0 for mapped patterns).
    static int listSize(PatternKind kind);
    bool isList() const { return listSize(kind) > 0; }

    // Colour-list patterns: the index of the colour at p.
    int index(const Vec3& p) const;
    // Colour-mapped patterns: the pattern function before the wave.
    double raw(const Vec3& p) const;
    // raw() after frequency, phase and the wave type: the colour map index.
    double value(const Vec3& p) const;
};

}  // namespace frameray::scene
