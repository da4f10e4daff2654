#include "scene/internal_functions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

#include "scene/noise.h"

namespace frameray::scene {

namespace {

using Formula = double (*)(const double* a);
// Why a call cannot run yet, from the arguments known at compile time.
using Refusal = std::string (*)(const double* a, const bool* known);

// A native function given by a plain formula over its arguments
// (a[0..2] = x, y, z, then the extra parameters).
class FormulaFunction final : public NativeFunction {
  public:
    FormulaFunction(Formula f, Refusal refuse) : f_(f), refuse_(refuse) {}
    double eval(const double* args) const override { return f_(args); }
    std::string unsupportedWith(const double* args, const bool* known) const override {
        return refuse_ ? refuse_(args, known) : std::string();
    }

  private:
    Formula f_;
    Refusal refuse_;
};

double radius(const double* a) {
    return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

// "Field strength" functions saturate at ±10 in povray (measured with
// f_paraboloid: -1.5 · 8.13 gives -10, -5 · -4.75 gives 10).
double field(double v) {
    return std::clamp(v, -10.0, 10.0);
}

double ellipsoid(const double* a) {
    // Extra parameters are inverse scales; povray returns the scaled
    // radius itself (no "- 1": measured).
    const double x = a[0] * a[3], y = a[1] * a[4], z = a[2] * a[5];
    return std::sqrt(x * x + y * y + z * z);
}

double paraboloid(const double* a) {
    return field(-a[3] * (a[0] * a[0] + a[2] * a[2] - a[1]));
}

double phi(const double* a) {
    const double r = radius(a);
    return r == 0 ? 0.0 : std::acos(a[1] / r);
}

double theta(const double* a) {
    return std::atan2(a[0], a[2]);
}

double roundedBox(const double* a) {
    // The distance to a box of half sizes a[4..6] with edges rounded by
    // a[3]; povray's values sit 1e-6 below the exact distance (measured).
    const double r = a[3];
    const double dx = std::max(std::abs(a[0]) - a[4] + r, 0.0);
    const double dy = std::max(std::abs(a[1]) - a[5] + r, 0.0);
    const double dz = std::max(std::abs(a[2]) - a[6] + r, 0.0);
    return std::sqrt(dx * dx + dy * dy + dz * dz) - r - 1e-6;
}

double sphere(const double* a) {
    return radius(a) - a[3];
}

double superellipsoid(const double* a) {
    // 1 - ((|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n))^(n/2) with e = a[3]
    // and n = a[4] (fitted to povray's values).
    const double e = a[3], n = a[4];
    const double xy = std::pow(std::abs(a[0]), 2 / e) + std::pow(std::abs(a[1]), 2 / e);
    const double s = std::pow(xy, e / n) + std::pow(std::abs(a[2]), 2 / n);
    return 1.0 - std::pow(s, n / 2);
}

double torus(const double* a) {
    const double ring = std::hypot(a[0], a[2]) - a[3];
    return std::sqrt(ring * ring + a[1] * a[1]) - a[4];
}

double sqr(double v) {
    return v * v;
}

// A "field strength" function: the strength a[3] times an algebraic
// surface's polynomial, saturated like every field function.
template <double (*Poly)(double, double, double)>
double fieldPoly(const double* a) {
    return field(a[3] * Poly(a[0], a[1], a[2]));
}

// ---- Algebraic surfaces with only a field strength (polynomials fitted
// to povray's values by least squares over 160 points each, then checked
// at more points; the named factorisations are the classic equations). ----

double crossedTrough(double x, double y, double z) {
    return x * x * z * z - y;
}

double cubicSaddle(double x, double y, double z) {
    return z + y * y * y - x * x * x;
}

// povray 3.7's f_odd gives exactly f_cushion's values (measured).
double cushion(double x, double y, double z) {
    const double x2 = x * x, y2 = y * y, z2 = z * z;
    return x2 + y2 - 2 * z2 + 2 * z2 * z + 2 * y2 * z - z2 * z2 - y2 * z2 - y2 * y2 + x2 * z2 -
           2 * x2 * y2 - x2 * x2;
}

double devilsCurve(double x, double y, double z) {
    const double x2 = x * x, y2 = y * y, z2 = z * z;
    return 0.36 * x2 - 0.25 * y2 + y2 * y2 - x2 * x2 - 2 * x2 * z2 - z2 * z2;
}

double glob(double x, double y, double z) {
    const double x4 = sqr(x * x);
    return 0.5 * x4 * x + 0.5 * x4 - y * y - z * z;
}

double heart(double x, double y, double z) {
    const double z3 = z * z * z;
    const double c = 2 * x * x + y * y + z * z - 1;
    return -c * c * c + y * y * z3 + 0.1 * x * x * z3;
}

double huntSurface(double x, double y, double z) {
    const double x2 = x * x, y2 = y * y, z2 = z * z;
    const double c = x2 + y2 + z2 - 13;
    return -(4 * c * c * c + 27 * sqr(3 * x2 + y2 - 4 * z2 - 12));
}

double kleinBottle(double x, double y, double z) {
    const double r2 = x * x + y * y + z * z;
    const double m = r2 - 2 * y - 1;
    return -((r2 + 2 * y - 1) * (m * m - 8 * z * z) + 16 * x * z * m);
}

double kummerV1(double x, double y, double z) {
    const double x2 = x * x, y2 = y * y, z2 = z * z;
    return x2 + y2 + z2 - 1 - (x2 * x2 + y2 * y2 + z2 * z2) + x2 * y2 + y2 * z2 + z2 * x2;
}

double lemniscateOfGerono(double x, double y, double z) {
    return x * x - sqr(x * x) - y * y - z * z;
}

double mitre(double x, double y, double z) {
    const double x2 = x * x, y2 = y * y, z2 = z * z;
    return y2 - y2 * z2 - y2 * y2 - 4 * x2 * (z2 + y2 + x2);
}

double nodalCubic(double /*x*/, double y, double z) {
    return 6 * y * z - z * z * z - y * y * y;
}

double pillow(double x, double y, double z) {
    const double x2 = x * x, y2 = y * y, z2 = z * z;
    return x2 * x2 + y2 * y2 + z2 * z2 - x2 - y2 - z2;
}

double piriform(double x, double y, double z) {
    return sqr(x * x) - x * x * x + y * y + z * z;
}

double quarticParaboloid(double x, double y, double z) {
    return y - sqr(x * x) - sqr(z * z);
}

double quarticSaddle(double x, double y, double z) {
    return y - sqr(x * x) + sqr(z * z);
}

double steinersRoman(double x, double y, double z) {
    const double x2 = x * x, y2 = y * y, z2 = z * z;
    return -(x * y * z + y2 * z2 + x2 * z2 + x2 * y2);
}

double torusGumdrop(double x, double y, double z) {
    const double x2 = x * x, yz = y * y + z * z;
    return -(4 * (x2 * x2 + yz * yz) + 17 * x2 * yz - 20 * (x2 + yz) + 17);
}

double umbrella(double x, double y, double z) {
    return y * z * z - x * x;
}

// Boy's surface: a sextic with √2 coefficients; fitted term by term.
double boySurface(const double* a) {
    const double x = a[0], y = a[1], z = a[2];
    struct Term {
        double c;
        int px, py, pz;
    };
    const double r = std::sqrt(2.0);
    const Term terms[] = {
        {64, 0, 0, 3},        {-288, 0, 0, 4},     {-144, 0, 2, 2},      {-144, 2, 0, 2},
        {432, 0, 0, 5},       {432 * r, 0, 3, 2},  {324, 0, 4, 1},       {-1296 * r, 2, 1, 2},
        {648, 2, 2, 1},       {324, 4, 0, 1},      {-216, 0, 0, 6},      {324, 0, 2, 4},
        {-432 * r, 0, 3, 3},  {-810, 0, 4, 2},     {-729, 0, 6, 0},      {648 * r, 1, 2, 3},
        {-2916 * r, 1, 4, 1}, {324, 2, 0, 4},      {1296 * r, 2, 1, 3},  {-1620, 2, 2, 2},
        {-2187, 2, 4, 0},     {-216 * r, 3, 0, 3}, {-1944 * r, 3, 2, 1}, {-810, 4, 0, 2},
        {-2187, 4, 2, 0},     {972 * r, 5, 0, 1},  {-729, 6, 0, 0},
    };
    double xp[7], yp[7], zp[7];
    xp[0] = yp[0] = zp[0] = 1;
    for (int i = 1; i < 7; ++i) {
        xp[i] = xp[i - 1] * x;
        yp[i] = yp[i - 1] * y;
        zp[i] = zp[i - 1] * z;
    }
    double sum = 0;
    for (const Term& t : terms) sum += t.c * xp[t.px] * yp[t.py] * zp[t.pz];
    // The "scale" parameter multiplies the value (measured: it does not
    // scale the shape, whatever functions.inc says).
    return field(a[3] * a[4] * sum);
}

// Enneper's surface in povray's form: with u = (y² - x²)/z,
// -(8/729)z⁶ - (2/27)u·z⁴ + (3/8)u² - (1/6)u²z² - (1/8)u³, times the field
// strength. For |z| < 0.2 povray divides by 0.2 instead of z (keeping z in
// the other terms), which keeps the value finite near z = 0 (fitted by
// least squares, the cut measured at ±0.2).
double enneper(const double* a) {
    const double x = a[0], y = a[1], z = a[2];
    const double u = (y * y - x * x) / (std::abs(z) < 0.2 ? 0.2 : z);
    const double z2 = z * z, z4 = z2 * z2;
    return field(a[3] * (-(8.0 / 729) * z4 * z2 - (2.0 / 27) * u * z4 + 0.375 * u * u -
                         u * u * z2 / 6 - u * u * u / 8));
}

// ---- Algebraic surfaces with shape parameters (a[3] is the field
// strength; the dependence on each parameter was fitted separately, then
// checked with all parameters random). ----

double bicorn(const double* a) {
    const double x = a[0], y = a[1], z = a[2], s = a[4];
    const double r2 = x * x + z * z;
    return field(a[3] * (y * y * (s * s - r2) - sqr(r2 + 2 * s * y - s * s)));
}

double bifolia(const double* a) {
    const double x = a[0], y = a[1], z = a[2];
    return field(a[3] * (a[4] * y * (x * x + z * z) - sqr(x * x + y * y + z * z)));
}

double torus2(const double* a) {
    const double x = a[0], y = a[1], z = a[2], major = a[4], minor = a[5];
    const double q = x * x + y * y + z * z + major * major - minor * minor;
    return field(-a[3] * (q * q - 4 * major * major * (x * x + z * z)));
}

double hyperbolicTorus(const double* a) {
    const double x = a[0], y = a[1], z = a[2], major = a[4], minor = a[5];
    const double q = x * x + y * y - z * z + major * major - minor * minor;
    return field(-a[3] * (q * q - 4 * major * major * (x * x - z * z)));
}

double parabolicTorus(const double* a) {
    const double x = a[0], y = a[1], z = a[2];
    const double diff = a[4] * a[4] - a[5] * a[5], sum = a[4] * a[4] + a[5] * a[5];
    return field(a[3] * (-sqr(x * x + y * y - z) + sum * (x * x - z) - diff * y * y - diff * diff));
}

double ovalsOfCassini(const double* a) {
    const double x = a[0], y = a[1], z = a[2], major = a[4], filling = a[5], thickness = a[6];
    const double m2 = major * major;
    return field(a[3] * (filling * filling - sqr(x * x + y * y + z * z + m2) +
                         thickness * m2 * (x * x + z * z)));
}

double quarticCylinder(const double* a) {
    const double x = a[0], y = a[1], z = a[2], d = a[4], w = a[5];
    const double r2 = x * x + z * z;
    return field(a[3] * (w * w * (d * d - r2) - y * y * r2));
}

double witchOfAgnesi(const double* a) {
    const double x = a[0], y = a[1], z = a[2], w = a[4];
    return field(a[3] * (w * (1 - y) - y * (x * x + z * z)));
}

double foliumSurface(const double* a) {
    const double x = a[0], y = a[1], z = a[2], neck = a[4], div = a[5];
    const double yz = y * y + z * z;
    return field(a[3] * (yz + (1 + div) * x * x - (4 * neck - div) * x * yz));
}

double kampyleOfEudoxus(const double* a) {
    const double x = a[0], y = a[1], z = a[2], dimple = a[4], c2 = a[5] * a[5];
    return field(a[3] * (c2 * sqr(x * x) - dimple * dimple * c2 * x * x - y * y - z * z));
}

double strophoid(const double* a) {
    const double x = a[0], y = a[1], z = a[2], size = a[4], sharp = a[5], fat = a[6];
    return field(a[3] * ((x - sharp) * (y * y + z * z) + fat * fat * x * x * (x + size)));
}

double kummerV2(const double* a) {
    const double x = a[0], y = a[1], z = a[2];
    const double x2 = x * x, y2 = y * y, z2 = z * z;
    return field(-a[3] * (x2 * x2 + y2 * y2 + z2 * z2 + a[4] * (x2 + y2 + z2) +
                          a[5] * (x2 * y2 + y2 * z2 + z2 * x2) + a[6] * x * y * z - 1));
}

// The distance from the y axis minus a quartic in y: a surface of
// revolution (no field saturation: measured).
double poly4(const double* a) {
    const double y = a[1];
    return std::hypot(a[0], a[2]) - (a[3] + y * (a[4] + y * (a[5] + y * (a[6] + y * a[7]))));
}

// ---- 2-D curves, optionally revolved ("SOR"). The last three extra
// parameters are the SOR switch, offset and angle: with the switch > 0 the
// curve's x is the distance from the y axis minus the offset, and the
// (x, y) plane is then turned by the angle in degrees; otherwise x and y
// are used as they are, offset and angle ignored (measured). ----

struct Plane {
    double x, y;
};

Plane sorPlane(const double* a, int switchIndex) {
    const double sw = a[switchIndex], offset = a[switchIndex + 1];
    if (!(sw > 0)) return {a[0], a[1]};
    const double u = std::hypot(a[0], a[2]) - offset;
    const double t = a[switchIndex + 2] * (M_PI / 180);
    const double c = std::cos(t), s = std::sin(t);
    return {u * c - a[1] * s, u * s + a[1] * c};
}

double algbrCyl1(double x, double y) {
    return y * y + std::abs(x) * x * x - x * x;
}
double algbrCyl2(double x, double y) {
    return -y * y + 2 * y * y * y + 3 * x * x * y - sqr(y * y) - 2 * sqr(x * x);
}
double algbrCyl3(double x, double y) {
    return -y * y + x * y * y + 2 * x * x * y - x * x * y * y - sqr(x * x);
}
double algbrCyl4(double x, double y) {
    return y * y * y - 3 * x * x * y - sqr(x * x + y * y);
}

// The algebraic cylinders saturate at their own limit (extra parameter 2)
// instead of 10.
template <double (*Curve)(double, double)>
double algebraicCylinder(const double* a) {
    const Plane p = sorPlane(a, 5);
    const double limit = a[4];
    return std::clamp(a[3] * Curve(p.x, p.y), -limit, limit);
}

double devilsCurve2d(const double* a) {
    const Plane p = sorPlane(a, 6);
    const double x2 = p.x * p.x, y2 = p.y * p.y;
    return field(a[3] * (a[4] * a[4] * x2 - a[5] * a[5] * y2 + y2 * y2 - x2 * x2));
}

double foliumSurface2d(const double* a) {
    const Plane p = sorPlane(a, 6);
    const double x = p.x, y2 = p.y * p.y, neck = a[4], div = a[5];
    return field(-a[3] * (y2 + (1 + div) * x * x - (4 * neck - div) * x * y2));
}

double kampyleOfEudoxus2d(const double* a) {
    const Plane p = sorPlane(a, 6);
    const double x2 = p.x * p.x, c = a[5];
    return field(a[3] * (c * c * x2 * x2 - a[4] * c * c * c * x2 - p.y * p.y));
}

double lemniscateOfGerono2d(const double* a) {
    const Plane p = sorPlane(a, 6);
    const double x2 = p.x * p.x, size = a[4], width = a[5];
    return field(a[3] * (width * width * (size * size * x2 - x2 * x2) - p.y * p.y));
}

double piriform2d(const double* a) {
    const Plane p = sorPlane(a, 7);
    const double x = p.x, x3 = x * x * x;
    return field(a[3] * (a[6] * a[6] * (a[4] * x3 + a[5] * x3 * x) - p.y * p.y));
}

double strophoid2d(const double* a) {
    const Plane p = sorPlane(a, 7);
    const double x = p.x, y2 = p.y * p.y;
    return field(a[3] * ((x - a[5]) * y2 + a[6] * a[6] * x * x * (x + a[4])));
}

double witchOfAgnesi2d(const double* a) {
    const Plane p = sorPlane(a, 6);
    return field(a[3] * (a[5] - a[4] * a[4] * p.y - p.x * p.x * p.y));
}

// ---- Blob-like fields. ----

// Two polynomial blob components (strength · (1 - (r / radius)²)², zero
// beyond the radius), centred at x = ∓separation/2; povray returns minus
// their sum.
double blob(const double* a) {
    const double x = a[0], yz = a[1] * a[1] + a[2] * a[2], half = a[3] / 2;
    auto component = [](double d2, double strength, double inverseRadius) {
        const double t = 1 - inverseRadius * inverseRadius * d2;
        return t > 0 ? strength * t * t : 0.0;
    };
    return -(component(sqr(x + half) + yz, a[4], a[5]) + component(sqr(x - half) + yz, a[6], a[7]));
}

// Two exponential blobs at the origin and at x = separation:
// threshold - strength · (e^(-k r1²) + e^(-k r2²)).
double blob2(const double* a) {
    const double x = a[0], yz = a[1] * a[1] + a[2] * a[2], k = a[4];
    return a[6] - a[5] * (std::exp(-k * (x * x + yz)) + std::exp(-k * (sqr(x - a[3]) + yz)));
}

// The exponents of three ellipsoids along the axes: each axis' own
// coordinate squared plus e times the other two squared.
std::array<double, 3> axisEllipsoids(const double* a, double e) {
    const double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
    return {x2 + e * (y2 + z2), y2 + e * (x2 + z2), z2 + e * (x2 + y2)};
}

// The union (nearest ellipsoid) and intersection (farthest) of the three.
double crossEllipsoids(const double* a) {
    const auto q = axisEllipsoids(a, a[3]);
    return a[6] - a[5] * std::exp(-a[4] * std::min({q[0], q[1], q[2]}));
}

double isectEllipsoids(const double* a) {
    const auto q = axisEllipsoids(a, a[3]);
    return a[6] - a[5] * std::exp(-a[4] * std::max({q[0], q[1], q[2]}));
}

// The three ellipsoids blended as exponential blobs.
double flangeCover(const double* a) {
    const auto q = axisEllipsoids(a, a[3]);
    const double k = a[4];
    return a[6] - a[5] * (std::exp(-k * q[0]) + std::exp(-k * q[1]) + std::exp(-k * q[2]));
}

// The blended ellipsoids (hollowness as the exponent scale) minus a
// central sphere blob (roundness, fatness), all times the size.
double spikes(const double* a) {
    const auto q = axisEllipsoids(a, a[3]);
    const double k = a[4], r2 = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
    return a[5] * (std::exp(-k * q[0]) + std::exp(-k * q[1]) + std::exp(-k * q[2]) -
                   a[7] * std::exp(-a[6] * r2));
}

// A height field: y minus a damped cosine bump.
double spikes2d(const double* a) {
    const double x = a[0], z = a[2];
    return a[1] -
           a[3] * std::cos(a[4] * x) * std::cos(a[5] * z) * std::exp(-a[6] * (x * x + z * z));
}

// ---- Helixes and the spiral. Their cross-section "type" t picks the norm
// (|u|^p + |v|^p)^(1/p) with p = 2/t: 0 square, 1 circle, 2 diamond,
// 3 concave diamond, fractions in between (measured at all of these). ----

double crossSectionNorm(double u, double v, double type) {
    u = std::abs(u);
    v = std::abs(v);
    if (type == 0) return std::max(u, v);
    const double p = 2 / type;
    return std::pow(std::pow(u, p) + std::pow(v, p), 1 / p);
}

// Helixes around the y axis: in the vertical half-plane through the point,
// u is the distance from the major radius and v the angle to the nearest
// of the n helixes divided by period · shape; (u, v) turned by the
// cross-section angle. The helixes cross angle atan2(z, x) = π/n - period·y
// (measured). povray caps the norm at ρ + R.
double helix1(const double* a) {
    const double x = a[0], y = a[1], z = a[2];
    const double n = a[3], period = a[4], minor = a[5], major = a[6], shape = a[7];
    const double rho = std::hypot(x, z);
    const double spacing = 2 * M_PI / n;
    double d = M_PI / n - std::atan2(z, x) - period * y;
    d -= spacing * std::floor(d / spacing + 0.5);
    const double u0 = rho - major, v0 = d / (period * shape);
    const double t = a[9] * (M_PI / 180), c = std::cos(t), s = std::sin(t);
    const double u = u0 * c + v0 * s, v = -u0 * s + v0 * c;
    return std::min(crossSectionNorm(u, v, a[8]), rho + major) - minor;
}

// A twisted rod: in the horizontal slice at height y the cross-section is
// centred at major · (cos θ, sin θ) with θ = period · y and turns with it.
// povray 3.7 ignores the number of helixes, the shape and the rotation
// angle here (measured).
double helix2(const double* a) {
    const double x = a[0], y = a[1], z = a[2];
    const double period = a[4], minor = a[5], major = a[6];
    const double t = period * y, c = std::cos(t), s = std::sin(t);
    const double dx = x - major * c, dz = z - major * s;
    return crossSectionNorm(dx * c + dz * s, -dx * s + dz * c, a[8]) - minor;
}

// An Archimedean spiral in the xz plane, windings a[3] apart, at radius
// a[3] · (1/2 - atan2(z, x) / 2π) + k; the cross-section spans (u, y).
// The norm is capped at the distance from the origin, and the value is at
// least that distance minus the "outer diameter" (measured; povray uses
// 1e-6 for the distance at the origin).
double spiral(const double* a) {
    const double x = a[0], y = a[1], z = a[2], spacing = a[3];
    const double rho = std::hypot(x, z);
    double u = 1e-6;
    if (rho != 0) {
        const double s = rho + spacing * std::atan2(z, x) / (2 * M_PI) - spacing / 2;
        u = s - spacing * std::floor(s / spacing + 0.5);
    }
    double r = std::sqrt(rho * rho + y * y);
    const double outside = r - a[5];
    if (r == 0) r = 1e-6;
    return std::max(std::min(crossSectionNorm(u, y, a[8]), r) - a[4], outside);
}

double noise3d(const double* a) {
    return solidNoise({a[0], a[1], a[2]}, NoiseGenerator::RangeCorrected);
}

double noise3dOriginal(const double* a) {
    return solidNoise({a[0], a[1], a[2]}, NoiseGenerator::Original);
}

double noise3dPerlin(const double* a) {
    return solidNoise({a[0], a[1], a[2]}, NoiseGenerator::Perlin);
}

// A torus (major radius a[3], in the xz plane) wound with a helical tube.
// In the torus' own coordinates — d the distance from the core circle,
// θ = atan2(x, z) around the y axis (π/2 on the y axis itself), ψ the angle
// around the core from the top towards the inside — a winding crosses
// angle u = N·θ - π - twist·ψ lies at a multiple of 2π. With du that
// angle wrapped to [-π, π):
//   n = min(√((d - m)² + fat2·du²), d + m)     m: the "minor radius"
//   groove = fat · cos(period · atan2(-amplitude·du, d - m) - phase·θ)
//   value = min(n - groove, ρ + R - m) - threshold
// (ρ the distance from the y axis). A negative radicand makes n NaN, and
// then the value is ρ + R - m - threshold: povray's comparisons keep the
// NaN through the first minimum and drop it at the second (all measured:
// 2000 random points over 280 random parameter sets, negative ones too).
double helicalTorus(const double* a) {
    const double x = a[0], y = a[1], z = a[2];
    const double major = a[3], windings = a[4], twist = a[5], fat = a[6], threshold = a[7];
    const double minor = a[8], fat2 = a[9], period = a[10], amplitude = a[11], phase = a[12];
    const double rho = std::sqrt(x * x + z * z);
    const double d = std::sqrt((rho - major) * (rho - major) + y * y);
    const double theta = rho != 0 ? std::atan2(x, z) : M_PI / 2;
    const double psi = std::atan2(major - rho, y);
    double du = windings * theta - M_PI - twist * psi;
    du -= 2 * M_PI * std::floor(du / (2 * M_PI) + 0.5);
    const double r2 = (d - minor) * (d - minor) + fat2 * du * du;
    double n = r2 >= 0 ? std::sqrt(r2) : std::nan("");
    if (d + minor < n) n = d + minor;
    const double groove =
        fat * std::cos(period * std::atan2(-amplitude * du, d - minor) - phase * theta);
    const double tube = n - groove, outside = rho + major - minor;
    return (tube < outside ? tube : outside) - threshold;
}

// A comma in the xz plane, scaled by s = a[3]: a head sphere of radius s/2
// at (s/2, 0, 0), united with a tail whose spine is the circle of radius
// 3s/4 about (-s/4, 0, 0) and whose tube radius (s/2)·cos(θ/2) shrinks from
// s/2 at the head to 0 at (-s, 0, 0) (θ = atan2(z, x)); the tail is cut at
// z = 0 (its value is at least -z). On the y axis povray moves x to 0.0001
// (measured: the origin gives -0.0001 at every scale; all pieces matched to
// 1e-15 at 3900 points, negative and zero scales included).
double comma(const double* a) {
    double x = a[0];
    const double y = a[1], z = a[2], s = a[3];
    if (x == 0 && z == 0) x = 0.0001;
    const double head = std::sqrt((x - 0.5 * s) * (x - 0.5 * s) + y * y + z * z) - 0.5 * s;
    const double spine = std::sqrt((x + 0.25 * s) * (x + 0.25 * s) + z * z) - 0.75 * s;
    const double tail = std::sqrt(spine * spine + y * y) - 0.5 * s * std::cos(std::atan2(z, x) / 2);
    return std::min(head, std::max(tail, -z));
}

// ---- Assorted shapes. ----

// A torus (axis y, radii a[4], a[5], centred at (a[6], a[7], 0)) inverted
// in the sphere of radius a[8] about the origin, times |p|⁴ to keep it a
// polynomial; povray's version carries an extra -8(R² - r²)·dy·y' term
// (y' the inverted y), measured by fitting each parameter separately.
double dupinCyclid(const double* a) {
    const double x = a[0], y = a[1], z = a[2];
    const double major = a[4], minor = a[5], dx = a[6], dy = a[7], inversion = a[8];
    const double r2 = x * x + y * y + z * z;
    const double k = inversion * inversion / r2;
    const double qx = x * k - dx, qy = y * k - dy, qz = z * k;
    const double m2 = major * major, d = m2 - minor * minor;
    const double q = qx * qx + qy * qy + qz * qz + d;
    return field(-a[3] * (q * q - 4 * m2 * (qx * qx + qz * qz) + 8 * d * dy * y * k) * r2 * r2);
}

// A woven grid: threads along x at z = k·dz whose height follows
// ±amplitude·cos(πx/dx), and threads along z at x = k·dx following
// ∓amplitude·cos(πz/dz), the sign alternating from thread to thread. The
// value is the distance to the nearer of the two threads on either side,
// horizontal part times a[5], vertical part times a[7] (measured).
double mesh1(const double* a) {
    const double x = a[0], y = a[1], z = a[2], dx = a[3], dz = a[4];
    const double flat = a[5], amplitude = a[6], tall = a[7];
    if (!(dx > 0) || !(dz > 0))
        throw std::runtime_error("not supported yet: f_mesh1 with a thread distance <= 0");
    double best = HUGE_VAL;
    auto consider = [&](double across, double height, double k) {
        const double sign = std::fmod(k, 2.0) != 0 ? -1.0 : 1.0;
        best = std::min(best, std::hypot(across * flat, (y - sign * height) * tall));
    };
    const double kz = std::floor(z / dz), waveX = amplitude * std::cos(M_PI * x / dx);
    for (double k : {kz, kz + 1}) consider(z - k * dz, waveX, k);
    const double kx = std::floor(x / dx), waveZ = -amplitude * std::cos(M_PI * z / dz);
    for (double k : {kx, kx + 1}) consider(x - k * dx, waveZ, k);
    return best;
}

// Pointy-top hexagons of inradius √3/2 tiling the xy plane (centres in
// rows 1.5 apart, every other row shifted by √3/2). f_hex_x is the
// hexagonal norm of the offset from the cell's centre; f_hex_y the distance
// to the nearest of the three lines through the centre at 0° and ±60°. The
// extra parameter does nothing (measured).
struct HexOffset {
    double norm, dx, dy;
};

HexOffset hexOffset(double x, double y) {
    const double s3 = std::sqrt(3.0);
    HexOffset best{HUGE_VAL, 0, 0};
    const double j0 = std::floor(y / 1.5);
    for (double j : {j0, j0 + 1}) {
        const double shift = std::fmod(j, 2.0) != 0 ? s3 / 2 : 0.0;
        const double i = std::floor((x - shift) / s3 + 0.5);
        const double dx = x - (i * s3 + shift), dy = y - 1.5 * j;
        const double n = std::max(std::abs(dx), std::abs(0.5 * dx) + std::abs(s3 / 2 * dy));
        if (n < best.norm) best = {n, dx, dy};
    }
    return best;
}

double hexX(const double* a) {
    return hexOffset(a[0], a[1]).norm;
}

double hexY(const double* a) {
    const HexOffset h = hexOffset(a[0], a[1]);
    const double c = std::sqrt(3.0) / 2;
    return std::min(
        {std::abs(h.dy), std::abs(c * h.dx + 0.5 * h.dy), std::abs(c * h.dx - 0.5 * h.dy)});
}

// int(a[3]) vertical tubes at horizontal distance poly(y) (a quartic with
// coefficients a[4..8]) from the y axis, the k-th at angle 2πk/a[3] from
// +z towards +x: the horizontal distance to the nearest one, 10000 when
// there are none (measured, with fractional counts too).
double polytubes(const double* a) {
    const double x = a[0], y = a[1], z = a[2], count = a[3];
    const double r = a[4] + y * (a[5] + y * (a[6] + y * (a[7] + y * a[8])));
    double best = 10000;
    const int n = count >= 1 ? static_cast<int>(count) : 0;
    for (int k = 0; k < n; ++k) {
        const double t = 2 * M_PI * k / count;
        best = std::min(best, std::hypot(x - r * std::sin(t), z - r * std::cos(t)));
    }
    return best;
}

// A d-orbital-like density: 1.2 - 1.6·e^(-1.33333332·r)·(3y² - r²)². The
// exponent's constant is povray's rounded 4/3, fitted to 2e-11 in the log;
// the extra parameter does nothing (measured).
double quantum(const double* a) {
    const double x = a[0], y = a[1], z = a[2];
    const double r2 = x * x + y * y + z * z;
    return 1.2 - 1.6 * std::exp(-1.33333332 * std::sqrt(r2)) * sqr(3 * y * y - r2);
}

// povray picks the generator from the integer part of the parameter, two
// lowest bits: 2 range-corrected, 3 (and -1) Perlin, anything else the
// original (measured with -1 … 5).
NoiseGenerator generatorParameter(double g) {
    switch (static_cast<int>(g) & 3) {
        case 2:
            return NoiseGenerator::RangeCorrected;
        case 3:
            return NoiseGenerator::Perlin;
        default:
            return NoiseGenerator::Original;
    }
}

double noiseGenerator(const double* a) {
    return solidNoise({a[0], a[1], a[2]}, generatorParameter(a[3]));
}

// Noise in [-1, 1] at p scaled by `scale`.
double signedNoise(const double* a, double scale, NoiseGenerator g) {
    return 2 * solidNoise({a[0] * scale, a[1] * scale, a[2] * scale}, g) - 1;
}

// Musgrave's ridged multifractal: each octave (1 - |noise|)-style ridges
// weighted by the previous octave's signal times the gain, clamped to
// [0, 1]; octave i scaled by lacunarity^(-i·H). Parameters H, lacunarity,
// octaves (loop while i < octaves), offset, gain, generator.
//
// povray 3.7 computes the per-octave weights once, at the first call of
// the run, and reuses them for every later call whatever its H, lacunarity
// or octaves (more octaves than the first call read unset weights).
// frameray uses each call's own parameters, which agrees whenever a scene
// uses one parameter set (all of povray's example scenes do).
double ridgedMf(const double* a) {
    const double h = a[3], lacunarity = a[4], octaves = a[5], offset = a[6], gain = a[7];
    const NoiseGenerator g = generatorParameter(a[8]);
    auto ridge = [&](double scale) {
        const double s = offset - std::abs(signedNoise(a, scale, g));
        return s * s;
    };
    double signal = ridge(1);
    double result = signal, frequency = 1;
    for (int i = 1; i < octaves; ++i) {
        frequency *= lacunarity;
        const double weight = std::clamp(signal * gain, 0.0, 1.0);
        signal = ridge(frequency) * weight;
        result += signal * std::pow(frequency, -h);
    }
    return result;
}

// Musgrave's heterogeneous terrain: value = offset + noise, then each
// octave adds (noise + offset) · lacunarity^(-i·H) · value^T (T, extra
// parameter 5, counts whole multiplications: T < 1 none). A fractional
// octave count adds that fraction of one more octave, multiplied by the
// value once whatever T is (measured).
double heteroMf(const double* a) {
    const double h = a[3], lacunarity = a[4], octaves = a[5], offset = a[6];
    const int t = a[7] >= 1 ? static_cast<int>(a[7]) : 0;
    const NoiseGenerator g = generatorParameter(a[8]);
    double value = offset + signedNoise(a, 1, g);
    double frequency = 1;
    int i = 1;
    for (; i < octaves; ++i) {
        frequency *= lacunarity;
        double increment = (signedNoise(a, frequency, g) + offset) * std::pow(frequency, -h);
        for (int k = 0; k < t; ++k) increment *= value;
        value += increment;
    }
    const double remainder = octaves - std::floor(octaves);
    if (remainder > 0) {
        frequency *= lacunarity;
        const double increment = (signedNoise(a, frequency, g) + offset) * std::pow(frequency, -h);
        value += remainder * increment * value;
    }
    return value;
}

// |ridge - noise| normalised to [0, 1] (noise in [0, 1]), averaged over
// octaves with weights omega^i at frequencies lambda^i, then the offset
// subtracted and the result normalised the same way. At least one octave;
// a fractional count adds that fraction of the next octave (measured).
double ridge(const double* a) {
    const double lambda = a[3], octaves = a[4], omega = a[5], offset = a[6], ridgeAt = a[7];
    const NoiseGenerator g = generatorParameter(a[8]);
    const double spread = std::abs(ridgeAt - 0.5) + 0.5;
    auto term = [&](double scale) {
        return std::abs(ridgeAt - solidNoise({a[0] * scale, a[1] * scale, a[2] * scale}, g)) /
               spread;
    };
    const int whole = std::max(1, static_cast<int>(octaves));
    double sum = 0, weights = 0, amplitude = 1, frequency = 1;
    for (int i = 0; i < whole; ++i) {
        sum += amplitude * term(frequency);
        weights += amplitude;
        amplitude *= omega;
        frequency *= lambda;
    }
    const double remainder = octaves - std::floor(octaves);
    if (remainder > 0) {
        sum += remainder * amplitude * term(frequency);
        weights += remainder * amplitude;
    }
    return (sum / weights - offset) / (std::abs(offset - 0.5) + 0.5);
}

// Parameter values frameray cannot match yet: refused when the call is
// compiled with them as constants (an isosurface cannot report an error
// mid-render), and by the formula itself otherwise.
std::string refuseMesh1(const double* a, const bool* known) {
    if ((known[3] && !(a[3] > 0)) || (known[4] && !(a[4] > 0)))
        return "f_mesh1 with a thread distance <= 0";
    return {};
}

struct Entry {
    std::string_view name;
    int extraParams;
    Formula formula;  // null: not implemented yet
    Refusal refuse = nullptr;
};

// functions.inc's internal functions by number (77 is unused).
constexpr std::array<Entry, 79> kInternals = {{
    {"f_algbr_cyl1", 5, algebraicCylinder<algbrCyl1>},
    {"f_algbr_cyl2", 5, algebraicCylinder<algbrCyl2>},
    {"f_algbr_cyl3", 5, algebraicCylinder<algbrCyl3>},
    {"f_algbr_cyl4", 5, algebraicCylinder<algbrCyl4>},
    {"f_bicorn", 2, bicorn},
    {"f_bifolia", 2, bifolia},
    {"f_blob", 5, blob},
    {"f_blob2", 4, blob2},
    {"f_boy_surface", 2, boySurface},
    {"f_comma", 1, comma},
    {"f_cross_ellipsoids", 4, crossEllipsoids},
    {"f_crossed_trough", 1, fieldPoly<crossedTrough>},
    {"f_cubic_saddle", 1, fieldPoly<cubicSaddle>},
    {"f_cushion", 1, fieldPoly<cushion>},
    {"f_devils_curve", 1, fieldPoly<devilsCurve>},
    {"f_devils_curve_2d", 6, devilsCurve2d},
    {"f_dupin_cyclid", 6, dupinCyclid},
    {"f_ellipsoid", 3, ellipsoid},
    {"f_enneper", 1, enneper},
    {"f_flange_cover", 4, flangeCover},
    {"f_folium_surface", 3, foliumSurface},
    {"f_folium_surface_2d", 6, foliumSurface2d},
    {"f_glob", 1, fieldPoly<glob>},
    {"f_heart", 1, fieldPoly<heart>},
    {"f_helical_torus", 10, helicalTorus},
    {"f_helix1", 7, helix1},
    {"f_helix2", 7, helix2},
    {"f_hex_x", 1, hexX},
    {"f_hex_y", 1, hexY},
    {"f_hetero_mf", 6, heteroMf},
    {"f_hunt_surface", 1, fieldPoly<huntSurface>},
    {"f_hyperbolic_torus", 3, hyperbolicTorus},
    {"f_isect_ellipsoids", 4, isectEllipsoids},
    {"f_kampyle_of_eudoxus", 3, kampyleOfEudoxus},
    {"f_kampyle_of_eudoxus_2d", 6, kampyleOfEudoxus2d},
    {"f_klein_bottle", 1, fieldPoly<kleinBottle>},
    {"f_kummer_surface_v1", 1, fieldPoly<kummerV1>},
    {"f_kummer_surface_v2", 4, kummerV2},
    {"f_lemniscate_of_gerono", 1, fieldPoly<lemniscateOfGerono>},
    {"f_lemniscate_of_gerono_2d", 6, lemniscateOfGerono2d},
    {"f_mesh1", 5, mesh1, refuseMesh1},
    {"f_mitre", 1, fieldPoly<mitre>},
    {"f_nodal_cubic", 1, fieldPoly<nodalCubic>},
    {"f_odd", 1, fieldPoly<cushion>},
    {"f_ovals_of_cassini", 4, ovalsOfCassini},
    {"f_paraboloid", 1, paraboloid},
    {"f_parabolic_torus", 3, parabolicTorus},
    {"f_ph", 0, phi},
    {"f_pillow", 1, fieldPoly<pillow>},
    {"f_piriform", 1, fieldPoly<piriform>},
    {"f_piriform_2d", 7, piriform2d},
    {"f_poly4", 5, poly4},
    {"f_polytubes", 6, polytubes},
    {"f_quantum", 1, quantum},
    {"f_quartic_paraboloid", 1, fieldPoly<quarticParaboloid>},
    {"f_quartic_saddle", 1, fieldPoly<quarticSaddle>},
    {"f_quartic_cylinder", 3, quarticCylinder},
    {"f_r", 0, radius},
    {"f_ridge", 6, ridge},
    {"f_ridged_mf", 6, ridgedMf},
    {"f_rounded_box", 4, roundedBox},
    {"f_sphere", 1, sphere},
    {"f_spikes", 5, spikes},
    {"f_spikes_2d", 4, spikes2d},
    {"f_spiral", 6, spiral},
    {"f_steiners_roman", 1, fieldPoly<steinersRoman>},
    {"f_strophoid", 4, strophoid},
    {"f_strophoid_2d", 7, strophoid2d},
    {"f_superellipsoid", 2, superellipsoid},
    {"f_th", 0, theta},
    {"f_torus", 2, torus},
    {"f_torus2", 3, torus2},
    {"f_torus_gumdrop", 1, fieldPoly<torusGumdrop>},
    {"f_umbrella", 1, fieldPoly<umbrella>},
    {"f_witch_of_agnesi", 2, witchOfAgnesi},
    {"f_witch_of_agnesi_2d", 6, witchOfAgnesi2d},
    {"f_noise3d", 0, noise3d},
    {"", 0, nullptr},
    {"f_noise_generator", 1, noiseGenerator},
}};

}  // namespace

InternalFunction internalFunction(int n, NoiseGenerator noise) {
    if (n < 0 || n >= static_cast<int>(kInternals.size())) return {};
    const Entry& e = kInternals[static_cast<size_t>(n)];
    InternalFunction result{std::string(e.name), e.extraParams, nullptr};
    auto formula = e.formula;
    if (formula == noise3d && noise == NoiseGenerator::Original) formula = noise3dOriginal;
    if (formula == noise3d && noise == NoiseGenerator::Perlin) formula = noise3dPerlin;
    if (formula) result.function = std::make_shared<FormulaFunction>(formula, e.refuse);
    return result;
}

}  // namespace frameray::scene
