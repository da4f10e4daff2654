#include "scene/noise.h"

#include <algorithm>
#include <array>

#include "scene/perlin_noise.h"
#include "util/lattice_hash.h"

namespace frameray::scene {

namespace {

// The gradient table: lattice cell hash h (0..255) uses entries h..h+3 as
// (constant, x, y, z) coefficients of its linear function, and the vector
// noise uses h+4.. and h+8.. for its y and z components, hence 256 + 11
// entries. Measured from povray 3.7 (f_noise3d and vturbulence at lattice
// points and along cell edges): every value has six significant digits.
constexpr std::array<double, 267> kGradients = {
    -1,        0.604974,  -0.937102,  0.414115,  0.576226,   -0.0161593, 0.432334,    0.103685,
    0.590539,  0.0286412, 0.46981,    -0.84622,  -0.0734112, -0.304097,  -0.40206,    -0.210132,
    -0.919127, 0.652033,  -0.83151,   -0.183948, -0.671107,  0.852476,   0.043595,    -0.404532,
    0.75494,   -0.335653, 0.618433,   0.605707,  0.708583,   -0.477195,  0.899474,    0.490623,
    0.221729,  -0.400381, -0.853727,  -0.932586, 0.659113,   0.961303,   0.325948,    -0.750851,
    0.842466,  0.734401,  -0.649866,  0.394491,  -0.466056,  -0.434073,  0.109026,    0.0847028,
    -0.738857, 0.241505,  0.16228,    -0.71426,  -0.883665,  -0.150408,  -0.90396,    -0.686549,
    -0.785214, 0.488548,  0.0246433,  0.142473,  -0.602136,  0.375845,   -0.00779736, 0.498955,
    -0.268147, 0.856382,  -0.386007,  -0.596094, -0.867735,  -0.570977,  -0.914366,   0.28896,
    0.672206,  -0.233783, 0.94815,    0.895262,  0.343252,   -0.173388,  -0.767971,   -0.314748,
    0.824308,  -0.342092, 0.721431,   -0.24004,  -0.63653,   0.553277,   0.376272,    0.158984,
    -0.452659, 0.396323,  -0.420676,  -0.454154, 0.122179,   0.295857,   0.0664225,   -0.202075,
    -0.724788, 0.453513,  0.224567,   -0.908812, 0.176349,   -0.320516,  -0.697139,   0.742702,
    -0.900786, 0.471489,  -0.133532,  0.119127,  -0.889769,  -0.23183,   -0.669673,   -0.046891,
    -0.803433, -0.966735, 0.475578,   -0.652644, 0.0112459,  -0.730007,  0.128283,    0.145647,
    -0.619318, 0.272023,  0.392966,   0.646418,  -0.0207675, -0.315908,  0.480797,    0.535668,
    -0.250172, -0.83093,  -0.653773,  -0.443809, 0.119982,   -0.897642,  0.89453,     0.165789,
    0.633875,  -0.886839, 0.930877,   -0.537194, 0.587732,   0.722011,   -0.209461,   -0.0424659,
    -0.814267, -0.919432, 0.280262,   -0.66302,  -0.558099,  -0.537469,  -0.598779,   0.929656,
    -0.170794, -0.537163, 0.312581,   0.959442,  0.722652,   0.499931,   0.175616,    -0.534874,
    -0.685115, 0.444999,  0.17171,    0.108202,  -0.768704,  -0.463828,  0.254231,    0.546014,
    0.869474,  0.875212,  -0.944427,  0.130724,  -0.110185,  0.312184,   -0.33138,    -0.629206,
    0.0606546, 0.722866,  -0.0979477, 0.821561,  0.0931258,  -0.972808,  0.0318151,   -0.867033,
    -0.387228, 0.280995,  -0.218189,  -0.539178, -0.427359,  -0.602075,  0.311971,    0.277974,
    0.773159,  0.592493,  -0.0331884, -0.630854, -0.269947,  0.339132,   0.581079,    0.209461,
    -0.317433, -0.284993, 0.181323,   0.341634,  0.804959,   -0.229572,  -0.758907,   -0.336721,
    0.605463,  -0.991272, -0.0188754, -0.300191, 0.368307,   -0.176135,  -0.3832,     -0.749569,
    0.62356,   -0.573938, 0.278309,   -0.971313, 0.839994,   -0.830686,  0.439078,    0.66128,
    0.694514,  0.0565042, 0.54342,    -0.438804, -0.0228428, -0.687068,  0.857267,    0.301991,
    -0.494255, -0.941039, 0.775509,   0.410575,  -0.362081,  -0.671534,  -0.348379,   0.932433,
    0.886442,  0.868681,  -0.225666,  -0.062211, -0.0976425, -0.641444,  -0.848112,   0.724697,
    0.473503,  0.998749,  0.174701,   0.559625,  -0.029099,  -0.337392,  -0.958129,   -0.659785,
    0.236042,  -0.246937, 0.659449,   -0.027512, 0.821897,   -0.226215,  0.0181735,   0.500481,
    -0.420127, -0.427878, 0.566186};

// Lattice coordinates are offset by this before wrapping to 12 bits, so that
// negative coordinates hash like positive ones further out (measured).
constexpr int kLatticeOffset = -10000;

struct Cell {
    int ix, iy, iz;     // wrapped lattice coordinates
    double fx, fy, fz;  // position inside the cell, [0, 1)
};

// POV-Ray floors negative coordinates with a 1e-10 tolerance, so a point a
// hair below an integer still counts as on it.
inline void latticeAxis(double v, int& cell, double& frac) {
    const int whole = v >= 0 ? latticeTruncate(v) : latticeTruncate(v - (1.0 - 1e-10));
    // Unsigned: INT_MIN and numbers near INT_MAX wrap, as the 12 bits want.
    cell = static_cast<int>((static_cast<unsigned>(whole) - static_cast<unsigned>(kLatticeOffset)) &
                            0xFFFu);
    frac = v - whole;
}

inline Cell cellOf(const Vec3& p) {
    Cell c{};
    latticeAxis(p.x, c.ix, c.fx);
    latticeAxis(p.y, c.iy, c.fy);
    latticeAxis(p.z, c.iz, c.fz);
    return c;
}

inline int hash2(int a, int b) {
    return kLatticeHash[kLatticeHash[a] ^ b];
}
inline int gradientIndex(int xy, int z) {
    return kLatticeHash[xy ^ z] & 0xFF;
}

inline double sCurve(double t) {
    return t * t * (3.0 - 2.0 * t);
}

// One corner's linear function at cell offset (x, y, z), weighted: t
// points at the corner's four coefficients (constant, x, y, z).
inline double corner(const double* t, double w, double x, double y, double z) {
    return w * (t[0] * 0.5 + t[1] * x + t[2] * y + t[3] * z);
}

// The eight corners of p's cell in POV-Ray's order (bit 0: x + 1, bit 1:
// y + 1, bit 2: z + 1): each one's coefficients in the gradient table,
// its weight and its offset from p. Calls visit(t, w, x, y, z) per corner.
// Written out flat: this runs once per noise octave, the hottest code of
// any textured scene.
template <typename Visit>
inline void visitCorners(const Vec3& p, Visit&& visit) {
    const Cell c = cellOf(p);
    const double sx = sCurve(c.fx), sy = sCurve(c.fy), sz = sCurve(c.fz);
    const double tx = 1 - sx, ty = 1 - sy, tz = 1 - sz;
    const double txty = tx * ty, sxty = sx * ty, txsy = tx * sy, sxsy = sx * sy;
    const int h00 = hash2(c.ix, c.iy), h10 = hash2(c.ix + 1, c.iy);
    const int h01 = hash2(c.ix, c.iy + 1), h11 = hash2(c.ix + 1, c.iy + 1);
    const double* g = kGradients.data();
    const double x0 = c.fx, x1 = c.fx - 1, y0 = c.fy, y1 = c.fy - 1;
    const double z0 = c.fz, z1 = c.fz - 1;
    visit(g + gradientIndex(h00, c.iz), txty * tz, x0, y0, z0);
    visit(g + gradientIndex(h10, c.iz), sxty * tz, x1, y0, z0);
    visit(g + gradientIndex(h01, c.iz), txsy * tz, x0, y1, z0);
    visit(g + gradientIndex(h11, c.iz), sxsy * tz, x1, y1, z0);
    visit(g + gradientIndex(h00, c.iz + 1), txty * sz, x0, y0, z1);
    visit(g + gradientIndex(h10, c.iz + 1), sxty * sz, x1, y0, z1);
    visit(g + gradientIndex(h01, c.iz + 1), txsy * sz, x0, y1, z1);
    visit(g + gradientIndex(h11, c.iz + 1), sxsy * sz, x1, y1, z1);
}

}  // namespace

double solidNoise(const Vec3& p, NoiseGenerator generator) {
    if (generator == NoiseGenerator::Perlin) return perlinNoise(p);
    double sum = 0;
    visitCorners(p, [&](const double* t, double w, double x, double y, double z) {
        sum += corner(t, w, x, y, z);
    });
    if (generator == NoiseGenerator::RangeCorrected) {
        // The raw sum spans about [-1.05242, 0.988997]; generator 2 maps
        // that onto [0, 1].
        sum = (sum + 1.05242) * 0.48985582;
    } else {
        sum += 0.5;
    }
    return std::clamp(sum, 0.0, 1.0);
}

namespace {

// The gradient table transposed for vector noise: entry g holds, for each
// of the four coefficients k (constant, x, y, z), the x, y and z
// components' coefficients (T[g + k], T[g + 4 + k], T[g + 8 + k]) and a
// zero, so one corner is four multiply-adds of four-lane vectors.
struct TransposedGradients {
    alignas(32) double v[256][4][4];
};
constexpr TransposedGradients transposeGradients() {
    TransposedGradients t{};
    for (int g = 0; g < 256; ++g)
        for (int k = 0; k < 4; ++k)
            for (int c = 0; c < 3; ++c) t.v[g][k][c] = kGradients[g + 4 * c + k];
    return t;
}
constexpr TransposedGradients kTransposed = transposeGradients();

struct CornerList {
    int g[8];
    double w[8], x[8], y[8], z[8];
};

inline CornerList cornerList(const Vec3& p) {
    CornerList k;
    int i = 0;
    const double* base = kGradients.data();
    visitCorners(p, [&](const double* t, double w, double x, double y, double z) {
        k.g[i] = static_cast<int>(t - base);
        k.w[i] = w;
        k.x[i] = x;
        k.y[i] = y;
        k.z[i] = z;
        ++i;
    });
    return k;
}

// Four doubles per value: one lane per component, the fourth unused.
// Lane by lane the same products and sums, in the same order, as corner()
// on each component, so the result is bit-identical to the scalar form on
// every CPU. Only AVX2 (no FMA: a fused multiply-add rounds differently).
__attribute__((target("avx2"))) Vec3 vectorNoiseAvx2(const Vec3& p) {
    typedef double Lanes __attribute__((vector_size(32)));
    const CornerList k = cornerList(p);
    Lanes sum = {0, 0, 0, 0};
    for (int i = 0; i < 8; ++i) {
        const Lanes* t = reinterpret_cast<const Lanes*>(kTransposed.v[k.g[i]]);
        const Lanes inner = t[0] * 0.5 + t[1] * k.x[i] + t[2] * k.y[i] + t[3] * k.z[i];
        sum += inner * k.w[i];
    }
    return {sum[0], sum[1], sum[2]};
}

}  // namespace

Vec3 vectorNoisePortable(const Vec3& p) {
    double rx = 0, ry = 0, rz = 0;
    visitCorners(p, [&](const double* t, double w, double x, double y, double z) {
        rx += corner(t, w, x, y, z);
        ry += corner(t + 4, w, x, y, z);
        rz += corner(t + 8, w, x, y, z);
    });
    return {rx, ry, rz};
}

Vec3 vectorNoise(const Vec3& p) {
    static const bool avx2 = __builtin_cpu_supports("avx2");
    return avx2 ? vectorNoiseAvx2(p) : vectorNoisePortable(p);
}

double turbulence(const Vec3& p, const Turbulence& turb, NoiseGenerator generator) {
    // Generators 2 and 3 stretch each octave to 2n - 0.5 (the first one
    // clamped to [0, 1]) so that their narrower range turbulates as much as
    // generator 1's.
    const bool stretch = generator != NoiseGenerator::Original;
    double value = solidNoise(p, generator);
    if (stretch) value = std::clamp(2.0 * value - 0.5, 0.0, 1.0);
    const double lambda = turb.lambda, omega = turb.omega;
    double l = lambda, o = omega;
    for (int i = 2; i <= turb.octaves; ++i) {
        const double n = solidNoise(p * l, generator);
        value += o * (stretch ? 2.0 * n - 0.5 : n);
        if (i < turb.octaves) {
            l *= lambda;
            o *= omega;
        }
    }
    return value;
}

Vec3 vectorTurbulence(const Vec3& p, const Turbulence& turb) {
    Vec3 result = vectorNoise(p);
    const double lambda = turb.lambda, omega = turb.omega;
    double l = lambda, o = omega;
    for (int i = 2; i <= turb.octaves; ++i) {
        result += vectorNoise(p * l) * o;
        if (i < turb.octaves) {
            l *= lambda;
            o *= omega;
        }
    }
    return result;
}

}  // namespace frameray::scene
