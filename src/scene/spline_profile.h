// Plane curves made of polynomial pieces, the profiles of lathe, sor and
// prism: each piece is a cubic (or lower) polynomial in its parameter
// s in [0, 1], built from the control points of povray's spline kinds
// (seed 000 §3.4: linear_spline, quadratic_spline, cubic_spline,
// bezier_spline).
#pragma once

#include <vector>

namespace frameray::scene {

struct ProfilePoint {
    double u = 0, v = 0;  // lathe: radius, height; prism: x, z
};

enum class SplineKind { Linear, Quadratic, Cubic, Bezier };

// One piece: u(s) = u[0] + u[1] s + u[2] s^2 + u[3] s^3, the same for v
// (increasing powers, as util/roots.h takes them), with its bounds.
struct ProfileSegment {
    double u[4] = {0, 0, 0, 0};
    double v[4] = {0, 0, 0, 0};
    double uMin = 0, uMax = 0, vMin = 0, vMax = 0;

    ProfilePoint at(double s) const;
    ProfilePoint tangent(double s) const;  // derivative in s
};

// The piece of `kind` whose control points start at `p`: 2 points for
// linear, 3 for quadratic (the piece runs from the second to the third, the
// first only helps set the start's slope), 4 for
// cubic (the outer two set the slopes, Catmull-Rom) and bezier.
ProfileSegment makeProfileSegment(SplineKind kind, const ProfilePoint* p);

// A piece with explicit coefficients (sor), bounds computed.
ProfileSegment profileSegmentFromCoefficients(const double u[4], const double v[4]);

// How many control points one piece uses, and how far the next piece
// starts (bezier pieces do not share points).
int pointsPerSegment(SplineKind kind);

// The parameter on `seg` closest to (u, v) among the points where the
// curve has that u or that v (exact for points on the curve) and the two
// ends; returns the squared distance.
double closestOnSegment(const ProfileSegment& seg, double u, double v, double& s);

// The least and greatest of c[0] + c[1] s + c[2] s^2 + c[3] s^3 over
// s in [0, 1].
void cubicRange(const double c[4], double& lo, double& hi);

// Roots in [lo, hi] of c[0] + c[1] s + c[2] s^2 + c[3] s^3 (fewer when
// the leading coefficients are zero), ascending; `roots` has room for 3.
int cubicRootsIn(const double c[4], double lo, double hi, double* roots);

}  // namespace frameray::scene
