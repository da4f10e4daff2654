// Normal perturbation (seed 003 §5.4.2): `normal { bumps | dents | wrinkles
// | ripples | waves | <any colour-mapped pattern> amount ... }` tilts the
// shading normal the way povray 3.7 does. The built-in normal patterns add
// a vector (vector noise, wave gradients) in pattern space; any other
// pattern is sampled at four points of a small tetrahedron around the hit
// point and the samples steer the normal.
#pragma once

#include <memory>

#include "scene/image_map.h"
#include "scene/patterns.h"
#include "util/matrix.h"
#include "util/vec3.h"

namespace frameray::scene {

struct Normal {
    // The pattern with its transformations, warps, turbulence, wave type,
    // frequency and phase.
    Pattern pattern;
    // The bump size (the number after the pattern, or bump_size).
    double amount = 0.5;
    // Size of the sampling tetrahedron for patterns that are not normal
    // patterns of their own (accuracy).
    double accuracy = 0.02;
    // bump_map: the image whose heights tilt the normal (the pattern's
    // chain still places it).
    std::shared_ptr<const ImageMap> bumpMap;

    // The perturbed unit normal at texture-space point p, where n is the
    // texture-space unit normal.
    Vec3 perturb(const Vec3& p, const Vec3& n) const;
};

}  // namespace frameray::scene
