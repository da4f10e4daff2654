#include "scene/patterns.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "scene/object.h"
#include "scene/texture.h"

namespace frameray::scene {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// Block patterns nudge the point so that faces lying exactly on a cell
// boundary (a plane at y = 0) fall into one cell instead of speckling;
// povray's nudge is 1e-10 (measured: a point 5e-11 below a boundary counts
// as on it, 2e-10 below does not).
constexpr double kBlockTolerance = 1e-10;

// Angle of (a, b) in [0, 1) turns, counter-clockwise from +a towards +b.
double turns(double a, double b) {
    double t = std::atan2(b, a) / kTwoPi;
    if (t < 0) t += 1.0;
    return t;
}

int checkerIndex(const Vec3& p) {
    const auto sum = static_cast<long long>(std::floor(p.x + kBlockTolerance) +
                                            std::floor(p.y + kBlockTolerance) +
                                            std::floor(p.z + kBlockTolerance));
    return static_cast<int>(sum & 1);
}

// Hexagons of unit side in the xz plane with corners on the x axis; cell
// (i, j) is centred at i*(1.5, sqrt3/2) + j*(0, sqrt3) and coloured
// (2i + j) mod 3, colour 0 at the origin.
}  // namespace

void nearestHexagon(double x, double z, double& rq, double& rr) {
    constexpr double kSqrt3 = 1.7320508075688772;
    const double q = x * (2.0 / 3.0);
    const double r = z / kSqrt3 - x / 3.0;
    const double s = -q - r;
    rq = std::round(q);
    rr = std::round(r);
    const double rs = std::round(s);
    const double dq = std::abs(rq - q), dr = std::abs(rr - r), ds = std::abs(rs - s);
    if (dq > dr && dq > ds)
        rq = -rr - rs;
    else if (dr > ds)
        rr = -rq - rs;
}

namespace {

int hexagonIndex(const Vec3& p) {
    double rq, rr;
    nearestHexagon(p.x, p.z, rq, rr);
    const long long m = (2 * static_cast<long long>(rq) + static_cast<long long>(rr)) % 3;
    return static_cast<int>(m < 0 ? m + 3 : m);
}

// Unit squares in the xz plane coloured so that no two sharing an edge or
// a corner match: going round a 2×2 block from the origin's square the
// indices are 0, 1 (z + 1), 2 (x + 1, z + 1), 3 (x + 1) (measured).
int squareIndex(const Vec3& p) {
    const auto ix = static_cast<long long>(std::floor(p.x + kBlockTolerance));
    const auto iz = static_cast<long long>(std::floor(p.z + kBlockTolerance));
    const int zOdd = static_cast<int>(iz & 1);
    return (ix & 1) == 0 ? zOdd : 3 - zOdd;
}

// Equilateral triangles of unit side in the xz plane, in rows along x of
// height sqrt(3)/2. In the sheared coordinates u = x - z/sqrt3,
// v = 2z/sqrt3 every unit cell holds a lower and an upper triangle; with
// k = (floor u - floor v) mod 3 the lower one takes (6 - 2k) mod 6 and the
// upper one (3 + 2k) mod 6 (measured from povray's renders).
int triangularIndex(const Vec3& p) {
    constexpr double kSqrt3 = 1.7320508075688772;
    const double u = p.x - p.z / kSqrt3, v = p.z * 2.0 / kSqrt3;
    const double fu = std::floor(u), fv = std::floor(v);
    long long k = (static_cast<long long>(fu) - static_cast<long long>(fv)) % 3;
    if (k < 0) k += 3;
    const bool upper = (u - fu) + (v - fv) >= 1.0;
    return static_cast<int>(upper ? (3 + 2 * k) % 6 : (6 - 2 * k) % 6);
}

// The six pyramids from the origin through the faces of a cube: +x 0,
// +y 1, +z 2, -x 3, -y 4, -z 5 by the largest coordinate (measured).
int cubicIndex(const Vec3& p) {
    const double ax = std::abs(p.x), ay = std::abs(p.y), az = std::abs(p.z);
    if (ax >= ay && ax >= az) return p.x >= 0 ? 0 : 3;
    if (ay >= az) return p.y >= 0 ? 1 : 4;
    return p.z >= 0 ? 2 : 5;
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

}  // namespace

Vec3 quiltOffset(const Vec3& p, double c0, double c1) {
    const Vec3 v{p.x - std::floor(p.x) - 0.5, p.y - std::floor(p.y) - 0.5,
                 p.z - std::floor(p.z) - 0.5};
    return v * quiltCurve(length(v), c0, c1);
}

namespace {

// The mean of the absolute coordinates of the offset from the unit cube's
// centre, scaled along its length by the quilt curve. povray scales the
// result by 2/sqrt(3), written as 1.154700538 (measured to 1e-15), and
// keeps the controls in single precision (the parser rounds them).
double quilted(const Vec3& p, double c0, double c1) {
    const Vec3 v = quiltOffset(p, c0, c1);
    return (std::abs(v.x) + std::abs(v.y) + std::abs(v.z)) / 3.0 * 1.154700538;
}

// The angle of (x, y) about the z axis in turns, measured from -y
// counter-clockwise (so +x is a quarter turn), 0 on the axis (measured).
double spiralTurns(double x, double y, double rad) {
    if (rad == 0) return 0;
    const double a = std::asin(y / rad);
    const double phi = x < 0 ? 1.5 * std::numbers::pi - a : 0.5 * std::numbers::pi + a;
    return phi / kTwoPi;
}

// The triangle wave of period 1 rising from 0 at whole numbers to 1 at
// halves (spiral2's building block).
double triangle(double v) {
    const double f = v - std::floor(v);
    return f < 0.5 ? 2.0 * f : 2.0 * (1.0 - f);
}

// spiral1: z + distance from the z axis + arms · angle, unwrapped (the wave
// wraps it). spiral2 adds the triangle waves of that sum and of the
// distance alone, which makes the arms cross (both fitted to povray's
// values to 1e-13).
double spiral(const Vec3& p, int arms, bool second) {
    const double rad = std::hypot(p.x, p.y);
    const double sum = p.z + rad + arms * spiralTurns(p.x, p.y, rad);
    return second ? triangle(sum) + triangle(rad) : sum;
}

}  // namespace

// The wave sources of ripples and waves: povray places number_of_waves
// (10 unless global_settings says) sources at the normalised vector noise
// of (i, 0, 0) and gives each a frequency from its SDL random generator
// (state' = state * 1812433253 + 12345, started at -560851967; bits 16..30
// scaled to [0.01, 1.01]); fewer or more sources are the first ones of the
// same sequence (measured: 1, 2, 3, 5 and 20 match povray).
std::shared_ptr<const WaveSources> makeWaveSources(int count) {
    auto w = std::make_shared<WaveSources>();
    std::uint32_t state = static_cast<std::uint32_t>(-560851967);
    for (int i = 0; i < count; ++i) {
        w->center.push_back(normalize(vectorNoise(Vec3(i, 0, 0))));
        state = state * 1812433253u + 12345u;
        w->frequency.push_back(static_cast<double>((state >> 16) & 0x7FFF) * 0.000030518509476 +
                               0.01);
    }
    return w;
}

const WaveSources& Pattern::waveSources() const {
    static const std::shared_ptr<const WaveSources> kDefault = makeWaveSources(kDefaultWaveCount);
    return waves ? *waves : *kDefault;
}

namespace {

double cycloidal(double v) {
    return std::sin(v * kTwoPi);
}

double ripplesValue(const Vec3& p, const WaveSources& w, double frequency, double phase) {
    const std::size_t n = w.center.size();
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
        double len = length(p - w.center[i]);
        if (len == 0) len = 1;
        sum += cycloidal(len * frequency + phase);
    }
    return 0.5 * (1.0 + sum / static_cast<double>(n));
}

double wavesValue(const Vec3& p, const WaveSources& w, double frequency, double phase) {
    const std::size_t n = w.center.size();
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
        double len = length(p - w.center[i]);
        if (len == 0) len = 1;
        sum += cycloidal(len * frequency * w.frequency[i] + phase) / w.frequency[i];
    }
    return 0.2 * (2.5 + sum / static_cast<double>(n));
}

double granite(const Vec3& p, NoiseGenerator gen) {
    double sum = 0, freq = 1;
    const Vec3 base = p * 4.0;
    for (int i = 0; i < 6; ++i, freq *= 2.0) {
        const double n = solidNoise(base * freq, gen);
        const double t = gen == NoiseGenerator::Original ? std::abs(0.5 - n)
                                                         : std::min(std::abs(1.0 - 2.0 * n), 0.5);
        sum += t / freq;
    }
    return sum;
}

double wrinkles(const Vec3& p, NoiseGenerator gen) {
    // Generators 2 and 3 stretch every octave to 2n - 0.5 clamped to [0, 1].
    auto octave = [gen](const Vec3& q) {
        const double n = solidNoise(q, gen);
        return gen == NoiseGenerator::Original ? n : std::clamp(2.0 * n - 0.5, 0.0, 1.0);
    };
    double value = octave(p), lambda = 2.0, omega = 0.5;
    for (int i = 1; i < 10; ++i, lambda *= 2.0, omega *= 0.5) value += omega * octave(p * lambda);
    return value / 2.0;
}

double wood(const Vec3& p, const std::optional<Turbulence>& turb) {
    double x = p.x, y = p.y;
    if (turb) {
        const Vec3 t = vectorTurbulence(p, *turb);
        x += cycloidal((p.x + t.x) * turb->amount.x);
        y += cycloidal((p.y + t.y) * turb->amount.y);
    }
    return std::sqrt(x * x + y * y);
}

double agate(const Vec3& p, const std::optional<Turbulence>& turb, double scale,
             NoiseGenerator gen) {
    // Agate always turbulates: without a turbulence of its own it uses
    // povray's defaults (6 octaves, omega 0.5, lambda 2).
    const double t = scale * turbulence(p, turb ? *turb : Turbulence{}, gen);
    double v = 0.5 * (cycloidal(1.3 * t + 1.1 * p.z) + 1.0);
    if (v < 0) return 0;
    return std::pow(std::min(1.0, v), 0.77);
}

}  // namespace

void Pattern::addTransform(const Transform& t) {
    if (!chain.empty() && chain.back().kind == Warp::Kind::Transform)
        chain.back().transform = chain.back().transform.then(t);
    else
        chain.push_back(Warp::makeTransform(t));
}

Vec3 Pattern::patternPoint(const Vec3& p) const {
    Vec3 q = p;
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) q = it->apply(q);
    // Agate turbulates inside the pattern with the turbulence's octaves,
    // omega and lambda, and a `turbulence` amount displaces its point as
    // for other patterns too (measured: agate turbulence 0.5 equals agate
    // warp { turbulence 0.5 }, stones2.inc T_Stone26).
    const bool usesTurbulence = kind == PatternKind::Marble || kind == PatternKind::Wood;
    if (turbulence && !usesTurbulence)
        q += mul(vectorTurbulence(q, *turbulence), turbulence->amount);
    return q;
}

int Pattern::listSize(PatternKind kind) {
    switch (kind) {
        case PatternKind::Checker:
            return 2;
        case PatternKind::Hexagon:
            return 3;
        case PatternKind::Brick:
        case PatternKind::Object:
            return 2;
        case PatternKind::Square:
            return 4;
        case PatternKind::Triangular:
        case PatternKind::Cubic:
            return 6;
        default:
            return 0;
    }
}

int Pattern::index(const Vec3& point) const {
    return indexAt(patternPoint(point));
}

int Pattern::indexAt(const Vec3& p) const {
    switch (kind) {
        case PatternKind::Checker:
            return checkerIndex(p);
        case PatternKind::Hexagon:
            return hexagonIndex(p);
        case PatternKind::Brick:
            return brickIndex(p, brickSize, mortar);
        case PatternKind::Object:
            return object && object->inside(p) ? 1 : 0;
        case PatternKind::Square:
            return squareIndex(p);
        case PatternKind::Triangular:
            return triangularIndex(p);
        case PatternKind::Cubic:
            return cubicIndex(p);
        default:
            return 0;
    }
}

namespace {

// pigment_pattern's grey: povray weighs the channels in single precision,
// products and sums alike (measured to 1e-17), and ignores filter and
// transmit; the grey is not clamped.
double pigmentGrey(const RGB& c) {
    return static_cast<double>(
        greySingle(static_cast<float>(c.r), static_cast<float>(c.g), static_cast<float>(c.b)));
}

// gradient and function patterns wrap values above one into [0, 1) before
// frequency and phase, but leave negative ones alone (measured).
double wrapAboveOne(double v) {
    return v > 1.0 ? std::fmod(v, 1.0) : v;
}
}  // namespace

namespace {

// slope: the normal's elevation towards the slope direction, 0 facing
// away, 0.5 across, 1 along it; plus the weighted altitude.
double slopeValue(const Pattern& pat, const Vec3& p, const Vec3& n) {
    auto mapRange = [](double v, double lo, double hi) {
        return hi != lo ? (v - lo) / (hi - lo) : v;
    };
    const double sLen = length(pat.slopeDirection), aLen = length(pat.altitudeDirection);
    double s = 0;
    if (sLen > 0) {
        const double c = std::clamp(dot(n, pat.slopeDirection) / sLen, -1.0, 1.0);
        s = mapRange(0.5 + std::asin(c) / std::numbers::pi, pat.slopeLow, pat.slopeHigh);
    }
    if (aLen == 0) return s;
    const double a =
        mapRange(dot(p, pat.altitudeDirection) / aLen, pat.altitudeLow, pat.altitudeHigh);
    return (sLen * s + aLen * a) / (sLen + aLen);
}

}  // namespace

double Pattern::raw(const Vec3& p, const SurfaceInfo* surface) const {
    switch (kind) {
        case PatternKind::Slope:
        case PatternKind::Aoi: {
            if (!surface) return 0.0;  // no surface (pattern functions, media)
            // povray takes the world-space normal and ray as they are: the
            // object's and the pattern's transformations do not turn them
            // (measured: slope y under rotate z*30 or scale <1,3,1> is
            // unchanged).
            const SurfaceInfo& s = *surface;
            if (kind == PatternKind::Slope) return slopeValue(*this, p, s.normal);
            return std::acos(std::clamp(dot(s.normal, s.direction), -1.0, 1.0)) / std::numbers::pi;
        }
        case PatternKind::Gradient:
            return wrapAboveOne(dot(p, gradient));
        case PatternKind::Function: {
            const double args[3] = {p.x, p.y, p.z};
            return wrapAboveOne(function->eval(args));
        }
        case PatternKind::Onion:
            // Wrapped by the pattern itself (measured: onion is 0 at a
            // distance of exactly 1 or 2, not the map's last colour).
            return std::fmod(length(p), 1.0);
        case PatternKind::Radial:
            return turns(p.x, -p.z);
        case PatternKind::Spherical:
            return std::max(0.0, 1.0 - length(p));
        case PatternKind::Cylindrical:
            return std::max(0.0, 1.0 - std::hypot(p.x, p.z));
        case PatternKind::Planar:
            return std::max(0.0, 1.0 - std::abs(p.y));
        case PatternKind::Boxed:
            return std::max(0.0, 1.0 - std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}));
        case PatternKind::Leopard: {
            const double s = (std::sin(p.x) + std::sin(p.y) + std::sin(p.z)) / 3.0;
            return s * s;
        }
        case PatternKind::Quilted:
            return quilted(p, control0, control1);
        case PatternKind::Spiral1:
            return spiral(p, arms, false);
        case PatternKind::Spiral2:
            return spiral(p, arms, true);
        case PatternKind::Cells:
            return cellsValue(p);
        case PatternKind::DensityFile:
            return density ? density->value(p, densityInterpolation) : 0.0;
        case PatternKind::PigmentPattern:
            return pigment ? pigmentGrey(pigment->at(p).rgb) : 0.0;
        case PatternKind::Bozo:
        case PatternKind::Spotted:
        case PatternKind::Bumps:
            return solidNoise(p, noiseGenerator);
        case PatternKind::Dents: {
            const double n = solidNoise(p, noiseGenerator);
            return n * n * n;
        }
        case PatternKind::Granite:
            return granite(p, noiseGenerator);
        case PatternKind::Marble:
            return p.x + (turbulence ? turbulence->amount.x *
                                           scene::turbulence(p, *turbulence, noiseGenerator)
                                     : 0.0);
        case PatternKind::Wood:
            return wood(p, turbulence);
        case PatternKind::Agate:
            return agate(p, turbulence, agateTurb, noiseGenerator);
        case PatternKind::Wrinkles:
            return wrinkles(p, noiseGenerator);
        case PatternKind::Ripples:
            return ripplesValue(p, waveSources(), frequency, phase);
        case PatternKind::Waves:
            return wavesValue(p, waveSources(), frequency, phase);
        case PatternKind::Image:
            return image ? image->valueAt(p) : 0.0;
        case PatternKind::Crackle:
            return scene::crackle(p, crackle, noiseGenerator);
        case PatternKind::Fractal:
            return fractalValue(p.x, p.y, fractal);
        case PatternKind::Tiling:
            return tilingValue(tiling, p);
        case PatternKind::Pavement:
            return pavementValue(pavement, p);
        default:
            return 0;
    }
}

double Pattern::value(const Vec3& p, const SurfaceInfo* surface) const {
    return wave(raw(patternPoint(p), surface));
}

double Pattern::wave(double rawValue) const {
    // ripples and waves use frequency and phase inside their sums as well
    // (measured: povray applies them twice for these two).
    double v = rawValue * frequency + phase;
    // POV-Ray wraps with a period a hair above one so that a value of
    // exactly 1 keeps the last colour of the map.
    v = std::fmod(v, 1.00001);
    if (v < 0) v -= std::floor(v);
    switch (waveType) {
        case WaveType::Ramp:
            return v;
        case WaveType::Triangle:
            return v < 0.5 ? 2.0 * v : 2.0 * (1.0 - v);
        case WaveType::Sine:
            return 0.5 * (1.0 + std::sin(kTwoPi * v));
        case WaveType::Scallop:
            return std::abs(std::sin(std::numbers::pi * v));
        case WaveType::Cubic:
            return v * v * (3.0 - 2.0 * v);
        case WaveType::Poly:
            return std::pow(v, exponent);
    }
    return v;
}

double PatternFunction::eval(const double* args) const {
    const Vec3 p{args[0], args[1], args[2]};
    if (!pattern_.isList()) return pattern_.value(p);
    // A list pattern gives its index as it is (5 for cubic's -z) unless
    // frequency, phase or the wave type differ from their defaults; then
    // the index goes through them like a mapped value (measured: checker
    // frequency 0.5 phase 0.1 gives 0.6 for index 1, brick frequency 3
    // phase 0.2 gives fmod(3.2, 1.00001)).
    const double index = pattern_.index(p);
    const bool plain =
        pattern_.frequency == 1 && pattern_.phase == 0 && pattern_.waveType == WaveType::Ramp;
    return plain ? index : pattern_.wave(index);
}

}  // namespace frameray::scene
