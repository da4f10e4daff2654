#include "scene/tiling.h"

#include <algorithm>
#include <cmath>
#include <span>

#include "scene/patterns.h"

namespace frameray::scene {

namespace {

constexpr double kSqrt3 = 1.7320508075688772;
constexpr double kPi = 3.14159265358979323846;

// Tiling 1: unit squares with edges on whole x and z; 1 - (distance to the
// nearest edge) / 0.5.
double squares(const Vec3& p) {
    const double fx = p.x - std::floor(p.x), fz = p.z - std::floor(p.z);
    const double d = std::min({fx, 1.0 - fx, fz, 1.0 - fz});
    return 1.0 - 2.0 * d;
}

// The distance from the centre of the nearest hexagon of unit side with
// corners along x, centred at (x0, 0) + i (1.5, sqrt3/2) + j (0, sqrt3), in
// units of its apothem (1 on the edges).
double hexagonalDistance(const Vec3& p, double x0) {
    const double x = p.x - x0, z = p.z;
    double rq, rr;
    nearestHexagon(x, z, rq, rr);
    const double dx = x - 1.5 * rq;
    const double dz = z - (kSqrt3 / 2.0) * rq - kSqrt3 * rr;
    const double c = kSqrt3 / 2.0;
    return std::max({std::abs(dz), std::abs(c * dx + 0.5 * dz), std::abs(c * dx - 0.5 * dz)}) / c;
}

// The unit triangles of tiling 3: whether p is in one pointing +z, and
// 1 - 3 * (distance to its nearest edge) / height (0 at the centre).
double triangleShade(const Vec3& p, bool& up) {
    const double u = p.x - p.z / kSqrt3, v = p.z * 2.0 / kSqrt3;
    const double fu = u - std::floor(u), fv = v - std::floor(v);
    up = fu + fv < 1.0;
    const double m =
        up ? std::min({fu, fv, 1.0 - fu - fv}) : std::min({1.0 - fu, 1.0 - fv, fu + fv - 1.0});
    return 1.0 - 3.0 * m;
}

// Tiling 2: hexagons of unit side with corners on the x axis, centred at
// (-1, 0) + i (1.5, sqrt3/2) + j (0, sqrt3) (the origin is a corner); the
// hexagonal distance from the centre, 1 on the edges.
double hexagons(const Vec3& p) {
    return hexagonalDistance(p, -1.0);
}

// Tiling 3: equilateral triangles of unit side, corners at i + j/2 along x
// and j sqrt3/2 along z. Triangles pointing +z take 0 to 0.5, those
// pointing -z 0.5 to 1, each rising from its centre: half of 1 - (distance
// to the nearest edge) / inradius.
double triangles(const Vec3& p) {
    bool up = false;
    const double shade = triangleShade(p, up);
    return up ? 0.5 * shade : 0.5 + 0.5 * shade;
}

// Tiling 7: octagons of unit side centred at (L i, L j), L = 1 + sqrt2,
// and unit squares turned 45 degrees between them. Both shade over the
// squares' inradius 0.5 (the octagons stay flat inside it): squares take
// 0 to 0.5, octagons 0.5 to 1.
double octagonsAndSquares(const Vec3& p) {
    constexpr double kSqrt2 = 1.4142135623730951;
    constexpr double kPeriod = 1.0 + kSqrt2, a = kPeriod / 2.0;
    const double fx = std::abs(p.x - kPeriod * std::round(p.x / kPeriod));
    const double fz = std::abs(p.z - kPeriod * std::round(p.z / kPeriod));
    if (fx + fz > a * kSqrt2) {
        // The square centred at the cell's corner (a, a).
        const double d = (kSqrt2 / 2.0 - (a - fx) - (a - fz)) / kSqrt2;
        return 0.5 * (1.0 - 2.0 * d);
    }
    const double d = std::min({a - fx, a - fz, (a * kSqrt2 - fx - fz) / kSqrt2});
    return 0.5 + 0.5 * std::max(0.0, 1.0 - 2.0 * d);
}

// Tiling 6: herringbone of 2 x 1 rectangles, lying ones [-3, -1] x [0, 1]
// and standing ones [-1, 0] x [-1, 1], repeated by (1, 1) and (2, -2).
// Lying ones take 0 to 0.5, standing ones 0.5 to 1, each 1 - 2 * (distance
// to the nearest edge).
double herringbone(const Vec3& p) {
    // Lattice coordinates: p = s (1, 1) + t (2, -2).
    const double s = std::floor((p.x + p.z) / 2.0), t = std::floor((p.x - p.z) / 4.0);
    const double bx = s + 2.0 * t, bz = s - 2.0 * t;
    struct Rect {
        double x0, x1, z0, z1;
    };
    constexpr Rect kLying{-3, -1, 0, 1}, kStanding{-1, 0, -1, 1};
    // The reduced point lies in the cell's parallelogram, which a few
    // translates of the two rectangles cover.
    for (int n = -2; n <= 2; ++n)
        for (int m = -1; m <= 1; ++m) {
            const double x = p.x - bx - n - 2.0 * m, z = p.z - bz - n + 2.0 * m;
            for (int kind = 0; kind < 2; ++kind) {
                const Rect& r = kind == 0 ? kLying : kStanding;
                if (x < r.x0 || x >= r.x1 || z < r.z0 || z >= r.z1) continue;
                const double d = std::min({x - r.x0, r.x1 - x, z - r.z0, r.z1 - z});
                return 0.5 * kind + 0.5 * (1.0 - 2.0 * d);
            }
        }
    return 0.0;
}

// A periodic tiling of convex tiles given as data: lattice vectors and the
// tiles of one cell, each with its kind. A point's tile is found among the
// translates near its cell; its value is (kind + 1 - d / shadeWidth) /
// kinds, d the distance to the tile's nearest edge, clamped at the centre.
struct Tile {
    int kind;
    std::span<const double> xz;  // corners counter-clockwise (x, z pairs)
    // Per-edge shade widths (edge i runs from corner i to corner i + 1);
    // empty: the tiling's shadeWidth for every edge.
    std::span<const double> widths = {};
};

struct LatticeTiling {
    double ax, az, bx, bz;  // lattice vectors
    int kinds;
    double shadeWidth;
    std::span<const Tile> tiles;
};

double latticeTilingValue(const LatticeTiling& t, const Vec3& p) {
    // Cell coordinates: p = s a + t b.
    const double det = t.ax * t.bz - t.az * t.bx;
    const double s = std::floor((p.x * t.bz - p.z * t.bx) / det);
    const double u = std::floor((t.ax * p.z - t.az * p.x) / det);
    // The point's own cell first: most points are found there.
    constexpr int kOffsets[] = {0, -1, 1, -2, 2};
    for (const int n : kOffsets)
        for (const int m : kOffsets) {
            const double ox = (s + n) * t.ax + (u + m) * t.bx;
            const double oz = (s + n) * t.az + (u + m) * t.bz;
            const double x = p.x - ox, z = p.z - oz;
            for (const Tile& tile : t.tiles) {
                const std::size_t count = tile.xz.size() / 2;
                double d = 1e300;
                bool inside = true;
                for (std::size_t i = 0; i < count && inside; ++i) {
                    const double x0 = tile.xz[2 * i], z0 = tile.xz[2 * i + 1];
                    const double x1 = tile.xz[(2 * i + 2) % (2 * count)];
                    const double z1 = tile.xz[(2 * i + 3) % (2 * count)];
                    const double ex = x1 - x0, ez = z1 - z0;
                    const double dist = (ex * (z - z0) - ez * (x - x0)) / std::hypot(ex, ez);
                    if (dist < 0) inside = false;
                    d = std::min(d, dist / (tile.widths.empty() ? t.shadeWidth : tile.widths[i]));
                }
                if (!inside) continue;
                return (tile.kind + std::max(0.0, 1.0 - d)) / t.kinds;
            }
        }
    return 0.0;
}

constexpr double kH = kSqrt3 / 2.0;

// Tiling 5: rows of unit rhombi of 60 degrees with edges along x, leaning
// right (kind 0) and left (kind 2), and standing ones between them (kind
// 1); lattice (3, 0) and (1.5, sqrt3/2); shaded over the rhombi's
// inradius sqrt3/4.
constexpr double kLeaningRight[] = {0, 0, 1, 0, 1.5, kH, 0.5, kH};
constexpr double kStanding[] = {1.5, -kH, 2, 0, 1.5, kH, 1, 0};
constexpr double kLeaningLeft[] = {-1, 0, 0, 0, -0.5, kH, -1.5, kH};
constexpr Tile kRhombi[] = {{0, kLeaningRight}, {1, kStanding}, {2, kLeaningLeft}};
constexpr LatticeTiling kTiling5{3, 0, 1.5, kH, 3, kSqrt3 / 4.0, kRhombi};

// Tiling 4: the right-leaning rhombi alone, lattice (1, 0) and (0.5,
// sqrt3/2).
constexpr Tile kLozenge[] = {{0, kLeaningRight}};
constexpr LatticeTiling kTiling4{1, 0, 0.5, kH, 1, kSqrt3 / 4.0, kLozenge};

// Tiling 8: rows of unit squares (kind 2) between rows of unit triangles
// pointing +z (kind 0) and -z (kind 1), each row of squares shifted half a
// square from the last; lattice (1, 0) and (0.5, 1 + sqrt3/2); shaded over
// the triangles' inradius sqrt3/6 (the squares stay flat inside it).
constexpr double kUpTriangle[] = {-0.5, -kH, 0.5, -kH, 0, 0};
constexpr double kDownTriangle[] = {0, 0, 0.5, -kH, 1, 0};
constexpr double kUnitSquare[] = {0, 0, 1, 0, 1, 1, 0, 1};
constexpr Tile kSquaresAndTriangles[] = {{0, kUpTriangle}, {1, kDownTriangle}, {2, kUnitSquare}};
// Tiling 9: hexagons of unit side (kind 2) with the triangles between them
// pointing +z (kind 0) and -z (kind 1); lattice (2, 0) and (1, sqrt3);
// shaded over the triangles' inradius.
constexpr double kTrihexUp[] = {-1, 0, 0, 0, -0.5, kH};
constexpr double kTrihexDown[] = {-0.5, kH, 0, 2 * kH, -1, 2 * kH};
constexpr double kTrihexHexagon[] = {0, 0, 1, 0, 1.5, kH, 1, 2 * kH, 0, 2 * kH, -0.5, kH};
constexpr Tile kTrihexagonal[] = {{0, kTrihexUp}, {1, kTrihexDown}, {2, kTrihexHexagon}};
constexpr LatticeTiling kTiling9{2, 0, 1, kSqrt3, 3, kSqrt3 / 6.0, kTrihexagonal};

// Tiling 10: unit squares in rows shifted by half a square (running bond);
// lattice (1, 0) and (0.5, 1).
constexpr Tile kBond[] = {{0, kUnitSquare}};
constexpr LatticeTiling kTiling10{1, 0, 0.5, 1, 1, 0.5, kBond};

// Tiling 11: in every 3 x 3 block a unit square (kind 0) pinwheeled by two
// lying 2 x 1 rectangles (kind 1) and two standing ones (kind 2).
constexpr double kPinSquare[] = {1, 1, 2, 1, 2, 2, 1, 2};
constexpr double kPinLying1[] = {0, 2, 2, 2, 2, 3, 0, 3};
constexpr double kPinLying2[] = {1, 0, 3, 0, 3, 1, 1, 1};
constexpr double kPinStanding1[] = {0, 0, 1, 0, 1, 2, 0, 2};
constexpr double kPinStanding2[] = {2, 1, 3, 1, 3, 3, 2, 3};
constexpr Tile kPinwheel[] = {
    {0, kPinSquare}, {1, kPinLying1}, {1, kPinLying2}, {2, kPinStanding1}, {2, kPinStanding2}};
constexpr LatticeTiling kTiling11{3, 0, 0, 3, 3, 0.5, kPinwheel};

// Tiling 12: a 6 x 6 block of unit squares (kind 0), lying 2 x 1
// rectangles (kind 1) and standing ones (kind 2), mapped from povray's
// values cell by cell.
constexpr double kBasketS0[] = {1, 1, 2, 1, 2, 2, 1, 2};
constexpr double kBasketS1[] = {4, 1, 5, 1, 5, 2, 4, 2};
constexpr double kBasketS2[] = {1, 4, 2, 4, 2, 5, 1, 5};
constexpr double kBasketS3[] = {4, 4, 5, 4, 5, 5, 4, 5};
constexpr double kBasketH0[] = {0, 2, 2, 2, 2, 3, 0, 3};
constexpr double kBasketH1[] = {0, 3, 2, 3, 2, 4, 0, 4};
constexpr double kBasketH2[] = {4, 2, 6, 2, 6, 3, 4, 3};
constexpr double kBasketH3[] = {4, 3, 6, 3, 6, 4, 4, 4};
constexpr double kBasketH4[] = {1, 5, 3, 5, 3, 6, 1, 6};
constexpr double kBasketH5[] = {3, 5, 5, 5, 5, 6, 3, 6};
constexpr double kBasketH6[] = {1, 0, 3, 0, 3, 1, 1, 1};
constexpr double kBasketH7[] = {3, 0, 5, 0, 5, 1, 3, 1};
constexpr double kBasketV0[] = {5, 4, 6, 4, 6, 6, 5, 6};
constexpr double kBasketV1[] = {0, 4, 1, 4, 1, 6, 0, 6};
constexpr double kBasketV2[] = {5, 0, 6, 0, 6, 2, 5, 2};
constexpr double kBasketV3[] = {0, 0, 1, 0, 1, 2, 0, 2};
constexpr double kBasketV4[] = {2, 3, 3, 3, 3, 5, 2, 5};
constexpr double kBasketV5[] = {3, 3, 4, 3, 4, 5, 3, 5};
constexpr double kBasketV6[] = {2, 1, 3, 1, 3, 3, 2, 3};
constexpr double kBasketV7[] = {3, 1, 4, 1, 4, 3, 3, 3};
constexpr Tile kBasketweave[] = {{0, kBasketS0}, {0, kBasketS1}, {0, kBasketS2}, {0, kBasketS3},
                                 {1, kBasketH0}, {1, kBasketH1}, {1, kBasketH2}, {1, kBasketH3},
                                 {1, kBasketH4}, {1, kBasketH5}, {1, kBasketH6}, {1, kBasketH7},
                                 {2, kBasketV0}, {2, kBasketV1}, {2, kBasketV2}, {2, kBasketV3},
                                 {2, kBasketV4}, {2, kBasketV5}, {2, kBasketV6}, {2, kBasketV7}};
constexpr LatticeTiling kTiling12{6, 0, 0, 6, 3, 0.5, kBasketweave};

// Tiling 18: 2 x 2 blocks in a checkerboard, split into two lying 2 x 1
// rectangles (kind 0) or two standing ones (kind 1); the block [0, 2] x
// [0, 2] stands.
constexpr double kWeaveStanding1[] = {0, 0, 1, 0, 1, 2, 0, 2};
constexpr double kWeaveStanding2[] = {1, 0, 2, 0, 2, 2, 1, 2};
constexpr double kWeaveStanding3[] = {2, 2, 3, 2, 3, 4, 2, 4};
constexpr double kWeaveStanding4[] = {3, 2, 4, 2, 4, 4, 3, 4};
constexpr double kWeaveLying1[] = {2, 0, 4, 0, 4, 1, 2, 1};
constexpr double kWeaveLying2[] = {2, 1, 4, 1, 4, 2, 2, 2};
constexpr double kWeaveLying3[] = {0, 2, 2, 2, 2, 3, 0, 3};
constexpr double kWeaveLying4[] = {0, 3, 2, 3, 2, 4, 0, 4};
constexpr Tile kBlockWeave[] = {{1, kWeaveStanding1}, {1, kWeaveStanding2}, {1, kWeaveStanding3},
                                {1, kWeaveStanding4}, {0, kWeaveLying1},    {0, kWeaveLying2},
                                {0, kWeaveLying3},    {0, kWeaveLying4}};
constexpr LatticeTiling kTiling18{4, 0, 0, 4, 2, 0.5, kBlockWeave};

// Tiling 15: the Pythagorean tiling of unit squares (kind 0) and 2 x 2
// squares (kind 1, flat inside the shade width 0.5); lattice (2, 1) and
// (1, -2).
constexpr double kPythagoreanBig[] = {-2, 0, 0, 0, 0, 2, -2, 2};
constexpr Tile kPythagorean[] = {{0, kUnitSquare}, {1, kPythagoreanBig}};
constexpr LatticeTiling kTiling15{2, 1, 1, -2, 2, 0.5, kPythagorean};

// Tiling 16: rhombitrihexagonal (3.4.6.4): unit hexagons (kind 2, one
// centred at (-1, 0) with corners along x), unit squares on their edges
// (kind 0) and triangles at their corners (kind 1); lattice (1 + sqrt3)
// (cos 30, sin 30) and (0, 1 + sqrt3); shaded over the triangles' inradius.
constexpr double kRhombiHexagon[] = {
    0,  0, -0.49999999999999989, 0.8660254037844386,   -1.4999999999999998,  0.86602540378443871,
    -2, 0, -1.5000000000000004,  -0.86602540378443837, -0.49999999999999989, -0.8660254037844386};
constexpr double kRhombiSquare1[] = {0,
                                     0,
                                     0.86602540378443871,
                                     0.49999999999999994,
                                     0.36602540378443882,
                                     1.3660254037844386,
                                     -0.49999999999999989,
                                     0.8660254037844386};
constexpr double kRhombiSquare2[] = {
    -0.49999999999999989, 0.8660254037844386, -0.49999999999999983, 1.8660254037844386,
    -1.4999999999999998,  1.8660254037844388, -1.4999999999999998,  0.86602540378443871};
constexpr double kRhombiSquare3[] = {-1.4999999999999998,
                                     0.86602540378443871,
                                     -2.3660254037844384,
                                     1.3660254037844386,
                                     -2.8660254037844388,
                                     0.50000000000000011,
                                     -2,
                                     0};
constexpr double kRhombiTriangle1[] = {
    0, 0, 0.86602540378443871, -0.49999999999999994, 0.86602540378443871, 0.49999999999999994};
constexpr double kRhombiTriangle2[] = {-0.49999999999999989, 0.8660254037844386,
                                       0.36602540378443882,  1.3660254037844386,
                                       -0.49999999999999983, 1.8660254037844386};
constexpr Tile kRhombitrihexagonal[] = {{2, kRhombiHexagon},   {0, kRhombiSquare1},
                                        {0, kRhombiSquare2},   {0, kRhombiSquare3},
                                        {1, kRhombiTriangle1}, {1, kRhombiTriangle2}};
constexpr LatticeTiling kTiling16{2.3660254037844388, 1.3660254037844384, 0, 2.7320508075688772, 3,
                                  kSqrt3 / 6.0,       kRhombitrihexagonal};
// Tiling 17: the same tiles in six kinds: squares facing 90, 30 and 150
// degrees 0, 1, 2; triangles at the hexagon's corners at 60 and 0 degrees
// 3 and 4; hexagons 5 (measured at each tile's centre).
constexpr Tile kRhombitrihexagonal6[] = {{5, kRhombiHexagon},   {1, kRhombiSquare1},
                                         {0, kRhombiSquare2},   {2, kRhombiSquare3},
                                         {4, kRhombiTriangle1}, {3, kRhombiTriangle2}};
constexpr LatticeTiling kTiling17{2.3660254037844388, 1.3660254037844384,  0, 2.7320508075688772, 6,
                                  kSqrt3 / 6.0,       kRhombitrihexagonal6};

// Tiling 22: truncated hexagonal (3.12.12): dodecagons of unit side (kind
// 2, one centred at (0, -0.5 - sqrt3/2) with an edge on z = 0.5) and the
// triangles between them pointing +z (kind 0) and -z (kind 1); lattice
// (2 + sqrt3) (1, 0) and (2 + sqrt3) (1/2, sqrt3/2).
constexpr double kDodecagon[] = {1.866025403784439,
                                 -0.8660254037844386,
                                 1.366025403784439,
                                 0,
                                 0.5,
                                 0.50000000000000044,
                                 -0.50000000000000022,
                                 0.50000000000000044,
                                 -1.3660254037844388,
                                 0,
                                 -1.8660254037844388,
                                 -0.86602540378443804,
                                 -1.866025403784439,
                                 -1.8660254037844388,
                                 -1.366025403784439,
                                 -2.7320508075688776,
                                 -0.49999999999999983,
                                 -3.2320508075688776,
                                 0.49999999999999917,
                                 -3.2320508075688776,
                                 1.3660254037844386,
                                 -2.7320508075688776,
                                 1.866025403784439,
                                 -1.8660254037844386};
constexpr double kTruncHexUp[] = {-0.5, 0.5, 0.5, 0.5, 0, 1.3660254037844386};
constexpr double kTruncHexDown[] = {1.3660254037844386, 0, 1.8660254037844386, -0.8660254037844386,
                                    2.3660254037844384, 0};
// The dodecagon shades over 1/3 from its edges facing +x, -x and -z and over
// the triangles' inradius from the others (measured: exact on 363 points).
constexpr double kW = kSqrt3 / 6.0, kThird = 1.0 / 3.0;
constexpr double kDodecagonWidths[] = {kW, kW, kW, kW, kW, kThird, kW, kW, kThird, kW, kW, kThird};
constexpr Tile kTruncatedHexagonal[] = {
    {0, kTruncHexUp}, {1, kTruncHexDown}, {2, kDodecagon, kDodecagonWidths}};
constexpr LatticeTiling kTiling22{3.7320508075688772, 0, 1.8660254037844386,
                                  3.2320508075688772, 3, kSqrt3 / 6.0,
                                  kTruncatedHexagonal};

// Tilings 23 and 24: truncated trihexagonal (4.6.12) of unit edges: a
// dodecagon centred at (0, -0.5 - sqrt3/2) with an edge on z = 0.5, the
// hexagons on every other edge (one centred at (0, 0.5 + sqrt3/2), corners
// along x) and squares between; lattice (3 + sqrt3) (1, 0) and (3 + sqrt3)
// (1/2, sqrt3/2); shaded over the squares' inradius 0.5. Tiling 23 has
// hexagons 0, squares 1, dodecagons 2; tiling 24 tells the squares' three
// directions apart.
// The same dodecagon as tiling 22's (kDodecagon).
constexpr double kTtHexagon1[] = {1.0000000000000002,   1.3660254037844386,   0.50000000000000033,
                                  2.2320508075688772,   -0.49999999999999961, 2.2320508075688772,
                                  -0.99999999999999978, 1.3660254037844388,   -0.50000000000000022,
                                  0.50000000000000022,  0.50000000000000033,  0.5};
constexpr double kTtHexagon2[] = {3.3660254037844388, 0,
                                  2.8660254037844388, 0.86602540378443837,
                                  1.866025403784439,  0.86602540378443849,
                                  1.3660254037844388, 0,
                                  1.8660254037844384, -0.8660254037844386,
                                  2.8660254037844388, -0.86602540378443882};
constexpr double kTtSquare1[] = {2.8660254037844384,   -0.8660254037844386, 1.8660254037844384,
                                 -0.86602540378443849, 1.8660254037844384,  -1.8660254037844386,
                                 2.8660254037844384,   -1.8660254037844388};
constexpr double kTtSquare2[] = {1,
                                 1.3660254037844384,
                                 0.5,
                                 0.49999999999999961,
                                 1.3660254037844384,
                                 0,
                                 1.8660254037844388,
                                 0.86602540378443793};
constexpr double kTtSquare3[] = {
    -1.8660254037844379,  0.86602540378443893, -1.3660254037844379,  0,
    -0.49999999999999933, 0.50000000000000011, -0.99999999999999944, 1.3660254037844388};
constexpr Tile kTruncTrihex3[] = {{0, kTtHexagon1}, {0, kTtHexagon2}, {1, kTtSquare1},
                                  {1, kTtSquare2},  {1, kTtSquare3},  {2, kDodecagon}};
constexpr LatticeTiling kTiling23{
    4.7320508075688767, 0, 2.3660254037844384, 4.0980762113533151, 3, 0.5, kTruncTrihex3};
constexpr Tile kTruncTrihex5[] = {{0, kTtHexagon1}, {0, kTtHexagon2}, {1, kTtSquare1},
                                  {2, kTtSquare2},  {3, kTtSquare3},  {4, kDodecagon}};
constexpr LatticeTiling kTiling24{
    4.7320508075688767, 0, 2.3660254037844384, 4.0980762113533151, 5, 0.5, kTruncTrihex5};

// Tiling 21: snub square (3.3.4.3.4) of unit edges: squares centred at
// (c, c) (kind 4) and (c, -c) (kind 5), c = (1 + sqrt3) / 4, turned by
// +-15 degrees, and triangles in four directions (kinds 0 to 3); lattice
// (2c, 2c) and (2c, -2c); shaded over the triangles' inradius.
constexpr double kQ = 0.5 + kH;  // 2c
constexpr double kSnubTriangle0[] = {0, -0.5, kH, 0, 0, 0.5};
constexpr double kSnubTriangle1[] = {0, 0.5, 0.5, kQ, -0.5, kQ};
constexpr double kSnubTriangle2[] = {0, -0.5, 0, 0.5, -kH, 0};
constexpr double kSnubTriangle3[] = {-0.5, -kQ, 0.5, -kQ, 0, -0.5};
constexpr double kSnubSquare1[] = {0, 0.5, kH, 0, kQ, kH, 0.5, kQ};
constexpr double kSnubSquare2[] = {0.5, -kQ, kQ, -kH, kH, 0, 0, -0.5};
constexpr Tile kSnubSquare[] = {{0, kSnubTriangle0}, {1, kSnubTriangle1}, {2, kSnubTriangle2},
                                {3, kSnubTriangle3}, {4, kSnubSquare1},   {5, kSnubSquare2}};
constexpr LatticeTiling kTiling21{kQ, kQ, kQ, -kQ, 6, kSqrt3 / 6.0, kSnubSquare};

// Tiling 14: squares of side sqrt2 (kind 4) on a 2 sqrt2 grid, the strips
// between them cut along their middles and, where they cross, along the
// diagonals: vertical halves west (kind 0) and east (kind 1), horizontal
// halves north (kind 2) and south (kind 3); shaded over sqrt2 / 4.
constexpr double kS2 = 1.4142135623730951, kHalfS2 = kS2 / 2.0, kTwoS2 = 2.0 * kS2;
constexpr double kCrossSquare[] = {kHalfS2,       kHalfS2,       kHalfS2 + kS2, kHalfS2,
                                   kHalfS2 + kS2, kHalfS2 + kS2, kHalfS2,       kHalfS2 + kS2};
constexpr double kCrossWest[] = {0, 0, 0, kTwoS2, -kHalfS2, kHalfS2 + kS2, -kHalfS2, kHalfS2};
constexpr double kCrossEast[] = {0, 0, kHalfS2, kHalfS2, kHalfS2, kHalfS2 + kS2, 0, kTwoS2};
constexpr double kCrossNorth[] = {0, 0, kTwoS2, 0, kHalfS2 + kS2, kHalfS2, kHalfS2, kHalfS2};
constexpr double kCrossSouth[] = {0, 0, kHalfS2, -kHalfS2, kHalfS2 + kS2, -kHalfS2, kTwoS2, 0};
constexpr Tile kCrossTiles[] = {
    {0, kCrossWest}, {1, kCrossEast}, {2, kCrossNorth}, {3, kCrossSouth}, {4, kCrossSquare}};
constexpr LatticeTiling kTiling14{kTwoS2, 0, 0, kTwoS2, 5, kS2 / 4.0, kCrossTiles};

// Tiling 13: the same tiles in three kinds: squares 0, horizontal halves 1,
// vertical halves 2.
constexpr Tile kCrossTiles3[] = {
    {2, kCrossWest}, {2, kCrossEast}, {1, kCrossNorth}, {1, kCrossSouth}, {0, kCrossSquare}};
constexpr LatticeTiling kTiling13{kTwoS2, 0, 0, kTwoS2, 3, kS2 / 4.0, kCrossTiles3};

constexpr LatticeTiling kTiling8{1, 0, 0.5, 1 + kH, 3, kSqrt3 / 6.0, kSquaresAndTriangles};

// Tilings of the unit triangles of tiling 3 where the six triangles round
// every vertex of an index-7 sublattice merge into a hexagon (snub
// hexagonal, 3.3.3.3.6): a vertex (u, v) (at x = u + v/2, z = v sqrt3/2) is
// a hexagon centre when (a (u - u0) + b (v - v0)) mod 7 is 0. Triangles pointing
// +z are kind 0, -z kind 1, hexagons kind 2 (flat inside the triangles'
// inradius).
double snubHexagonal(const Vec3& p, long long u0, long long v0, long long a, long long b) {
    const double u = p.x - p.z / kSqrt3, v = p.z * 2.0 / kSqrt3;
    const double iu = std::floor(u), iv = std::floor(v);
    const double fu = u - iu, fv = v - iv;
    const bool up = fu + fv < 1.0;
    const auto cu = static_cast<long long>(iu), cv = static_cast<long long>(iv);
    const long long corners[3][2] = {
        {up ? cu : cu + 1, up ? cv : cv + 1}, {cu + 1, cv}, {cu, cv + 1}};
    for (const auto& c : corners) {
        const long long r = (a * (c[0] - u0) + b * (c[1] - v0)) % 7;
        if (r != 0) continue;
        const Vec3 centre{static_cast<double>(c[0]) + 0.5 * static_cast<double>(c[1]), 0,
                          kSqrt3 / 2.0 * static_cast<double>(c[1])};
        // hexagonalDistance measures from the lattice through x0; shift the
        // point so that this centre is the lattice's origin.
        const double h = hexagonalDistance(p - centre, 0.0);
        const double d = kSqrt3 / 2.0 * (1.0 - h);
        return (2.0 + std::max(0.0, 1.0 - d / (kSqrt3 / 6.0))) / 3.0;
    }
    const double m =
        up ? std::min({fu, fv, 1.0 - fu - fv}) : std::min({1.0 - fu, 1.0 - fv, fu + fv - 1.0});
    return ((up ? 0.0 : 1.0) + 1.0 - 3.0 * m) / 3.0;
}

}  // namespace

bool tilingSupported(int n) {
    return n >= 1 && n <= 24;
}

double tilingValue(int n, const Vec3& p) {
    switch (n) {
        case 1:
            return squares(p);
        case 2:
            return hexagons(p);
        case 3:
            return triangles(p);
        case 4:
            return latticeTilingValue(kTiling4, p);
        case 5:
            return latticeTilingValue(kTiling5, p);
        case 6:
            return herringbone(p);
        case 7:
            return octagonsAndSquares(p);
        case 8:
            return latticeTilingValue(kTiling8, p);
        case 9:
            return latticeTilingValue(kTiling9, p);
        case 10:
            return latticeTilingValue(kTiling10, p);
        case 11:
            return latticeTilingValue(kTiling11, p);
        case 12:
            return latticeTilingValue(kTiling12, p);
        case 13:
            return latticeTilingValue(kTiling13, p);
        case 14:
            return latticeTilingValue(kTiling14, p);
        case 15:
            return latticeTilingValue(kTiling15, p);
        case 16:
            return latticeTilingValue(kTiling16, p);
        case 17:
            return latticeTilingValue(kTiling17, p);
        case 18:
            return latticeTilingValue(kTiling18, p);
        case 19:
            // Centres at (-1, 0) + the lattice of (1, 2) and (-2, 3).
            return snubHexagonal(p, -1, 0, 3, 2);
        case 20:
            // The mirror image: centres at (0.5, -sqrt3/2) + the lattice of
            // (2, 1) and (-1, 3).
            return snubHexagonal(p, 1, -1, 3, 1);
        case 21:
            return latticeTilingValue(kTiling21, p);
        case 22:
            return latticeTilingValue(kTiling22, p);
        case 23:
            return latticeTilingValue(kTiling23, p);
        case 24:
            return latticeTilingValue(kTiling24, p);
        default:
            return 0.0;
    }
}

namespace {

// pavement number_of_sides 4 number_of_tiles 2: dominoes [0, 1] x [0, 2]
// in columns, shaded like the squares (interior and form change nothing,
// measured).
constexpr double kDomino[] = {0, 0, 1, 0, 1, 2, 0, 2};
constexpr Tile kDominoes[] = {{0, kDomino}};
constexpr LatticeTiling kPavementDominoes{1, 0, 0, 2, 1, 0.5, kDominoes};

// number_of_sides 4 number_of_tiles 3 pattern 1: straight trominoes
// [0, 3] x [0, 1] in rows.
constexpr double kTromino[] = {0, 0, 3, 0, 3, 1, 0, 1};
constexpr Tile kTrominoes[] = {{0, kTromino}};
constexpr LatticeTiling kPavementTrominoes{3, 0, 0, 1, 1, 0.5, kTrominoes};

// number_of_sides 3 number_of_tiles 2: lozenges leaning left (tiling 4's
// mirrored), shaded over the triangles' inradius (flat inside).
constexpr Tile kLozengeLeft[] = {{0, kLeaningLeft}};
constexpr LatticeTiling kPavementLozenges{1, 0, 0.5, kH, 1, kSqrt3 / 6.0, kLozengeLeft};

// number_of_sides 6 number_of_tiles 2: the hexagons of the single-cell
// pavement (centred at (1, 0) + i (1.5, sqrt3/2) + j (0, sqrt3)) joined in
// pairs, (i, j) with even i to (i + 1, j - 1) (measured); shaded over
// sqrt3/6 from the point's own hexagon's other five edges.
double hexagonPairs(const Vec3& p) {
    const double x = p.x - 1.0, z = p.z;
    double rq, rr;
    nearestHexagon(x, z, rq, rr);
    const bool first = std::fmod(std::abs(rq), 2.0) == 0.0;
    const double pq = first ? rq + 1 : rq - 1, pr = first ? rr - 1 : rr + 1;
    auto centre = [](double i, double j) {
        return std::pair{1.0 + 1.5 * i, kSqrt3 / 2.0 * i + kSqrt3 * j};
    };
    const auto [ax, az] = centre(rq, rr);
    const auto [bx, bz] = centre(pq, pr);
    // The distance to the point's own hexagon's five other edges, as lines
    // (measured: povray ignores the partner's edges).
    double d = 1e300;
    for (int k = 0; k < 6; ++k) {
        const double a = (k + 0.5) * kPi / 3.0;
        const double nx = std::cos(a), nz = std::sin(a);
        if (std::abs(ax + kSqrt3 * nx - bx) < 1e-9 && std::abs(az + kSqrt3 * nz - bz) < 1e-9)
            continue;
        d = std::min(d, kSqrt3 / 2.0 - ((p.x - ax) * nx + (p.z - az) * nz));
    }
    return std::max(0.0, 1.0 - d / (kSqrt3 / 6.0));
}

}  // namespace

double pavementValue(const PavementSettings& s, const Vec3& p) {
    if (s.tiles == 3 && s.sides == 4 && s.exterior == 0)
        return latticeTilingValue(kPavementTrominoes, p);
    if (s.tiles == 2 && s.sides == 6) return hexagonPairs(p);
    if (s.tiles == 2 && s.sides == 3) return latticeTilingValue(kPavementLozenges, p);
    if (s.tiles == 2 && s.sides == 4) {
        if (s.exterior == 0) return latticeTilingValue(kPavementDominoes, p);
        // Corners cut or rounded: the offset from the domino's middle
        // segment x = 0.5, z in [0.5, 1.5], measured as for the squares.
        const double dx = std::abs(p.x - std::floor(p.x) - 0.5);
        const double fz = p.z - 2.0 * std::floor(p.z / 2.0);
        const double dz = std::max(0.0, std::abs(fz - 1.0) - 0.5);
        const double r = s.exterior == 1 ? dx + dz : std::hypot(dx, dz);
        return std::min(1.0, 2.0 * r);
    }
    switch (s.sides) {
        case 4: {
            // Unit squares with edges on whole x and z, shaded by the
            // distance from the centre: the largest offset (exterior 0),
            // their sum (1: corners cut) or their length (2: corners
            // rounded), twice that capped at 1.
            const double dx = std::abs(p.x - std::floor(p.x) - 0.5);
            const double dz = std::abs(p.z - std::floor(p.z) - 0.5);
            const double r = s.exterior == 1   ? dx + dz
                             : s.exterior == 2 ? std::hypot(dx, dz)
                                               : std::max(dx, dz);
            return std::min(1.0, 2.0 * r);
        }
        case 6:
            // Hexagons of unit side centred at (1, 0) + the lattice (the
            // mirror image of tiling 2's), shaded over the width sqrt3/6
            // from the edges and 0 further in.
            return std::max(0.0, 1.0 - 3.0 * (1.0 - hexagonalDistance(p, 1.0)));
        default: {
            bool up = false;
            return triangleShade(p, up);
        }
    }
}

}  // namespace frameray::scene
