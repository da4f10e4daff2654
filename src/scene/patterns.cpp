#include "scene/patterns.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace frameray::scene {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// Block patterns nudge the point so that faces lying exactly on a cell
// boundary (a plane at y = 0) fall into one cell instead of speckling.
constexpr double kBlockTolerance = 1e-3;

// Angle of (a, b) in [0, 1) turns, counter-clockwise from +a towards +b.
double turns(double a, double b) {
    double t = std::atan2(b, a) / kTwoPi;
    if (t < 0) t += 1.0;
    return t;
}

int checkerIndex(const Vec3& p) {
    const auto sum = static_cast<long long>(std::floor(p.x + kBlockTolerance) + std::floor(p.y + kBlockTolerance) +
                                            std::floor(p.z + kBlockTolerance));
    return static_cast<int>(sum & 1);
}

// Hexagons of unit side in the xz plane with corners on the x axis; cell
// (i, j) is centred at i*(1.5, sqrt3/2) + j*(0, sqrt3) and coloured
// (2i + j) mod 3, colour 0 at the origin.
int hexagonIndex(const Vec3& p) {
    constexpr double kSqrt3 = 1.7320508075688772;
    const double q = p.x * (2.0 / 3.0);
    const double r = p.z / kSqrt3 - p.x / 3.0;
    const double s = -q - r;
    double rq = std::round(q), rr = std::round(r);
    const double rs = std::round(s);
    const double dq = std::abs(rq - q), dr = std::abs(rr - r), ds = std::abs(rs - s);
    if (dq > dr && dq > ds) rq = -rr - rs;
    else if (dr > ds) rr = -rq - rs;
    const long long m = (2 * static_cast<long long>(rq) + static_cast<long long>(rr)) % 3;
    return static_cast<int>(m < 0 ? m + 3 : m);
}

// Bricks of brickSize laid in courses along y.
// The mortar fills the top end of each cell in every axis. Index 0 is the
// mortar, 1 the brick.
int brickIndex(const Vec3& p, const Vec3& size, double mortar) {
    double x = p.x + kBlockTolerance, y = p.y + kBlockTolerance, z = p.z + kBlockTolerance;
    const double course = std::floor(y / size.y);
    y -= course * size.y;
    // Odd courses shift half a brick in x, even ones half a brick in z.
    if (std::fmod(course, 2.0) != 0)
        x += size.x * 0.5;
    else
        z += size.z * 0.5;
    x -= std::floor(x / size.x) * size.x;
    z -= std::floor(z / size.z) * size.z;
    const bool inMortar = x >= size.x - mortar || y >= size.y - mortar || z >= size.z - mortar;
    return inMortar ? 0 : 1;
}

double quiltCurve(double t, double c0, double c1) {
    // Cubic Bezier from 0 to 1 with inner control values c0 and c1.
    const double u = 1.0 - t;
    return t * t * t + 3.0 * t * u * u * c0 + 3.0 * t * t * u * c1;
}

double quilted(const Vec3& p, double c0, double c1) {
    Vec3 v{p.x - std::floor(p.x) - 0.5, p.y - std::floor(p.y) - 0.5, p.z - std::floor(p.z) - 0.5};
    v = v * quiltCurve(length(v), c0, c1);
    return (std::abs(v.x) + std::abs(v.y) + std::abs(v.z)) / 3.0;
}

double spiral(const Vec3& p, int arms, bool second) {
    const double r = std::hypot(p.x, p.y);
    const double a = turns(p.x, p.y) * arms;
    double v = second ? a - r : a + r;
    (void)p.z;
    return v;
}

}  // namespace

int Pattern::listSize(PatternKind kind) {
    switch (kind) {
        case PatternKind::Checker: return 2;
        case PatternKind::Hexagon: return 3;
        case PatternKind::Brick: return 2;
        default: return 0;
    }
}

int Pattern::index(const Vec3& p) const {
    switch (kind) {
        case PatternKind::Checker: return checkerIndex(p);
        case PatternKind::Hexagon: return hexagonIndex(p);
        case PatternKind::Brick: return brickIndex(p, brickSize, mortar);
        default: return 0;
    }
}

double Pattern::raw(const Vec3& p) const {
    switch (kind) {
        case PatternKind::Gradient: return dot(p, gradient);
        case PatternKind::Onion: return length(p);
        case PatternKind::Radial: return turns(p.x, -p.z);
        case PatternKind::Spherical: return std::max(0.0, 1.0 - length(p));
        case PatternKind::Cylindrical: return std::max(0.0, 1.0 - std::hypot(p.x, p.z));
        case PatternKind::Planar: return std::max(0.0, 1.0 - std::abs(p.y));
        case PatternKind::Boxed:
            return std::max(0.0, 1.0 - std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}));
        case PatternKind::Leopard: {
            const double s = (std::sin(p.x) + std::sin(p.y) + std::sin(p.z)) / 3.0;
            return s * s;
        }
        case PatternKind::Quilted: return quilted(p, control0, control1);
        case PatternKind::Spiral1: return spiral(p, arms, false);
        case PatternKind::Spiral2: return spiral(p, arms, true);
        default: return 0;
    }
}

double Pattern::value(const Vec3& p) const {
    double v = raw(p) * frequency + phase;
    // POV-Ray wraps with a period a hair above one so that a value of
    // exactly 1 keeps the last colour of the map.
    v = std::fmod(v, 1.00001);
    if (v < 0) v -= std::floor(v);
    switch (wave) {
        case WaveType::Ramp: return v;
        case WaveType::Triangle: return v < 0.5 ? 2.0 * v : 2.0 * (1.0 - v);
        case WaveType::Sine: return 0.5 * (1.0 + std::sin(kTwoPi * v));
        case WaveType::Scallop: return std::abs(std::sin(std::numbers::pi * v));
        case WaveType::Cubic: return v * v * (3.0 - 2.0 * v);
        case WaveType::Poly: return std::pow(v, exponent);
    }
    return v;
}

}  // namespace frameray::scene
