// Bounds of the zero set of a polynomial in x, y, z (poly, cubic, quartic).
//
// povray treats these surfaces as unbounded, so a scene that uses one
// (pawns.pov's torus-shaped quartics) tests it with every ray. Many are
// closed surfaces, though: when the top-degree part of the polynomial is
// provably positive in every direction, the polynomial is positive
// beyond some radius and the surface lies inside a ball. An
// octree search by interval arithmetic then shrinks the ball's box to the
// cells where the surface can be. Conservative: a box found here always
// holds every point where the polynomial is <= 0, with a margin for
// rounding.
#pragma once

#include <vector>

#include "scene/ray.h"

namespace frameray::scene {

// One monomial coefficient * x^i y^j z^k.
struct PolynomialTerm {
    int i, j, k;  // powers of x, y, z
    double coefficient;
};

struct PolynomialBounds {
    // Holds the whole surface (the zero set); infinite when no proof of
    // boundedness was found.
    Bounds surface = Bounds::infinite();
    // Holds the inside (where the polynomial is negative): the same box.
    Bounds inside = Bounds::infinite();
};

PolynomialBounds polynomialBounds(const std::vector<PolynomialTerm>& terms);

}  // namespace frameray::scene
