#include "scene/perlin_noise.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace frameray::scene {

namespace {

constexpr int kCells = 2048;  // lattice period along each axis
constexpr int kMask = kCells - 1;

// Coordinates are shifted by this before flooring, so that negative
// coordinates need no special case (povray's rollover constant; the shift
// also costs the fractional part its last bits, as povray's).
constexpr double kShift = 10000000.023157213;

struct Tables {
    std::array<Vec3, kCells> gradient;
    std::array<int, kCells> permutation;
};

// 15 bits per draw from state' = state * 1812433253 + 12345.
class TableGenerator {
  public:
    explicit TableGenerator(std::uint32_t seed) : state_(seed) {}
    int draw() {
        state_ = state_ * 1812433253u + 12345u;
        return static_cast<int>((state_ >> 16) & 0x7FFFu);
    }

  private:
    std::uint32_t state_;
};

Tables buildTables() {
    Tables t{};
    TableGenerator gen(1);
    // Gradients: components (d mod 4096 - 2048) / 2048, drawn x, y, z
    // until the vector lies inside the unit ball (and not at its centre),
    // then normalised.
    for (Vec3& g : t.gradient) {
        double lengthSq = 0;
        Vec3 v;
        do {
            v.x = static_cast<double>(gen.draw() % (2 * kCells) - kCells) / kCells;
            v.y = static_cast<double>(gen.draw() % (2 * kCells) - kCells) / kCells;
            v.z = static_cast<double>(gen.draw() % (2 * kCells) - kCells) / kCells;
            lengthSq = v.x * v.x + v.y * v.y + v.z * v.z;
        } while (lengthSq > 1.0 || lengthSq < 1.0e-5);
        const double len = std::sqrt(lengthSq);
        g = {v.x / len, v.y / len, v.z / len};
    }
    // Permutation: the identity plus one extra slot (2048, holding 0), then
    // swaps of every even slot from 2048 down to 2 with a drawn partner in
    // [0, 2048). Only slots 0..2047 are read afterwards (indices wrap), so
    // the value the first swap parks in slot 2048 is lost and 0 appears
    // twice: povray's permutation is not quite one, and this keeps it so.
    std::array<int, kCells + 1> perm{};
    for (int i = 0; i < kCells; ++i) perm[static_cast<size_t>(i)] = i;
    perm[kCells] = 0;
    for (int i = kCells; i > 0; i -= 2) {
        const int j = gen.draw() % kCells;
        std::swap(perm[static_cast<size_t>(i)], perm[static_cast<size_t>(j)]);
    }
    std::copy_n(perm.begin(), kCells, t.permutation.begin());
    return t;
}

const Tables& tables() {
    static const Tables t = buildTables();  // immutable once built
    return t;
}

struct Axis {
    int cell;     // lattice cell, wrapped to [0, 2048)
    double frac;  // offset from the cell's lower corner, [0, 1)
};

inline Axis axisOf(double v) {
    const double shifted = v + kShift;
    const double f = std::floor(shifted);
    // Past int's range the x86 conversion povray relies on yields INT_MIN.
    const int whole = (f >= -2147483648.0 && f < 2147483648.0) ? static_cast<int>(f)
                                                               : std::numeric_limits<int>::min();
    return {whole & kMask, shifted - whole};
}

inline double fade(double t) {
    return t * t * (3.0 - 2.0 * t);
}
inline double mix(double t, double a, double b) {
    return a + t * (b - a);
}
inline double dot(const Vec3& g, double x, double y, double z) {
    return x * g.x + y * g.y + z * g.z;
}

}  // namespace

double perlinGradientNoise(const Vec3& p) {
    const Tables& t = tables();
    const Axis ax = axisOf(p.x), ay = axisOf(p.y), az = axisOf(p.z);
    const auto perm = [&](int i) { return t.permutation[static_cast<size_t>(i & kMask)]; };
    const auto grad = [&](int i) -> const Vec3& {
        return t.gradient[static_cast<size_t>(i & kMask)];
    };
    const int px0 = perm(ax.cell), px1 = perm(ax.cell + 1);
    const int h00 = perm(px0 + ay.cell), h10 = perm(px1 + ay.cell);
    const int h01 = perm(px0 + ay.cell + 1), h11 = perm(px1 + ay.cell + 1);
    const double x0 = ax.frac, y0 = ay.frac, z0 = az.frac;
    const double x1 = x0 - 1.0, y1 = y0 - 1.0, z1 = z0 - 1.0;
    const double sx = fade(x0), sy = fade(y0), sz = fade(z0);

    // One z layer of the cell: bilinear blend of the four corner values.
    const auto layer = [&](int zc, double z) {
        const double bottom =
            mix(sx, dot(grad(h00 + zc), x0, y0, z), dot(grad(h10 + zc), x1, y0, z));
        const double top = mix(sx, dot(grad(h01 + zc), x0, y1, z), dot(grad(h11 + zc), x1, y1, z));
        return mix(sy, bottom, top);
    };
    const double near = layer(az.cell, z0);
    const double far = layer(az.cell + 1, z1);
    return mix(sz, near, far);
}

double perlinNoise(const Vec3& p) {
    return std::clamp(0.5 * (1.59 * perlinGradientNoise(p) + 0.985), 0.0, 1.0);
}

}  // namespace frameray::scene
