#include "scene/spline_profile.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "util/roots.h"

namespace frameray::scene {

namespace {

double poly3(const double c[4], double s) {
    return ((c[3] * s + c[2]) * s + c[1]) * s + c[0];
}
double slope3(const double c[4], double s) {
    return (3 * c[3] * s + 2 * c[2]) * s + c[1];
}

}  // namespace

// The ends and the zeros of the derivative.
void cubicRange(const double c[4], double& lo, double& hi) {
    lo = std::min(c[0], poly3(c, 1));
    hi = std::max(c[0], poly3(c, 1));
    double r[2];
    const int n = solveQuadratic(c[1], 2 * c[2], 3 * c[3], r);
    for (int i = 0; i < n; ++i)
        if (r[i] > 0 && r[i] < 1) {
            const double x = poly3(c, r[i]);
            lo = std::min(lo, x);
            hi = std::max(hi, x);
        }
}

namespace {

// Power-basis coefficients of a cubic Hermite piece from p0 to p1 with
// end slopes m0, m1.
void hermite(double p0, double p1, double m0, double m1, double c[4]) {
    c[0] = p0;
    c[1] = m0;
    c[2] = 3 * (p1 - p0) - 2 * m0 - m1;
    c[3] = 2 * (p0 - p1) + m0 + m1;
}

void coefficients(SplineKind kind, const double* p, double c[4]) {
    switch (kind) {
        case SplineKind::Linear:
            c[0] = p[0];
            c[1] = p[1] - p[0];
            c[2] = c[3] = 0;
            return;
        case SplineKind::Quadratic:
            // From p1 to p2 leaving p1 with slope (p2 - p0) / 2 (povray 3.7's
            // quadratic_spline, measured).
            c[0] = p[1];
            c[1] = 0.5 * (p[2] - p[0]);
            c[2] = p[2] - p[1] - c[1];
            c[3] = 0;
            return;
        case SplineKind::Cubic:
            // From p1 to p2 with Catmull-Rom slopes.
            hermite(p[1], p[2], 0.5 * (p[2] - p[0]), 0.5 * (p[3] - p[1]), c);
            return;
        case SplineKind::Bezier:
            c[0] = p[0];
            c[1] = 3 * (p[1] - p[0]);
            c[2] = 3 * (p[2] - 2 * p[1] + p[0]);
            c[3] = p[3] - 3 * p[2] + 3 * p[1] - p[0];
            return;
    }
}

}  // namespace

ProfilePoint ProfileSegment::at(double s) const {
    return {poly3(u, s), poly3(v, s)};
}
ProfilePoint ProfileSegment::tangent(double s) const {
    return {slope3(u, s), slope3(v, s)};
}

int pointsPerSegment(SplineKind kind) {
    switch (kind) {
        case SplineKind::Linear:
            return 2;
        case SplineKind::Quadratic:
            return 3;
        default:
            return 4;
    }
}

ProfileSegment profileSegmentFromCoefficients(const double u[4], const double v[4]) {
    ProfileSegment seg;
    std::copy(u, u + 4, seg.u);
    std::copy(v, v + 4, seg.v);
    cubicRange(seg.u, seg.uMin, seg.uMax);
    cubicRange(seg.v, seg.vMin, seg.vMax);
    return seg;
}

ProfileSegment makeProfileSegment(SplineKind kind, const ProfilePoint* p) {
    const int n = pointsPerSegment(kind);
    double us[4] = {0, 0, 0, 0}, vs[4] = {0, 0, 0, 0};
    for (int i = 0; i < n; ++i) {
        us[i] = p[i].u;
        vs[i] = p[i].v;
    }
    double u[4], v[4];
    coefficients(kind, us, u);
    coefficients(kind, vs, v);
    return profileSegmentFromCoefficients(u, v);
}

int cubicRootsIn(const double c[4], double lo, double hi, double* roots) {
    int degree = 3;
    while (degree > 0 && c[degree] == 0) --degree;
    if (degree == 0) return 0;
    return realRootsInInterval(std::span<const double>(c, static_cast<size_t>(degree) + 1), lo, hi,
                               roots);
}

double closestOnSegment(const ProfileSegment& seg, double u, double v, double& s) {
    double best = std::numeric_limits<double>::infinity();
    auto consider = [&](double candidate) {
        const ProfilePoint p = seg.at(candidate);
        const double d = (p.u - u) * (p.u - u) + (p.v - v) * (p.v - v);
        if (d < best) {
            best = d;
            s = candidate;
        }
    };
    consider(0);
    consider(1);
    double roots[3];
    for (int coord = 0; coord < 2; ++coord) {
        const double* src = coord == 0 ? seg.u : seg.v;
        const double c[4] = {src[0] - (coord == 0 ? u : v), src[1], src[2], src[3]};
        const int n = cubicRootsIn(c, 0, 1, roots);
        for (int i = 0; i < n; ++i) consider(roots[i]);
    }
    return best;
}

}  // namespace frameray::scene
