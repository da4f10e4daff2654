#include "scene/crackle.h"

#include <algorithm>
#include <cmath>

#include "util/lattice_hash.h"

namespace frameray::scene {

namespace {

// Cells hash by their coordinates' low 12 bits (two's complement, so -1 is
// 4095), unlike solid noise's offset lattice (measured).
int cellHash(int ix, int iy, int iz) {
    return kLatticeHash[kLatticeHash[kLatticeHash[ix & 0xFFF] ^ (iy & 0xFFF)] ^ (iz & 0xFFF)];
}

}  // namespace

Vec3 crackleFeaturePoint(int ix, int iy, int iz) {
    const int h = cellHash(ix, iy, iz);
    return {ix + kCrackleTable[h], iy + kCrackleTable[h + 1], iz + kCrackleTable[h + 2]};
}

double cellsValue(const Vec3& p) {
    constexpr double kNudge = 1e-10;
    const int ix = latticeFloor(p.x + kNudge);
    const int iy = latticeFloor(p.y + kNudge);
    const int iz = latticeFloor(p.z + kNudge);
    return kCrackleTable[static_cast<std::size_t>(cellHash(ix, iy, iz))];
}

namespace {

// The distance for `metric`, with the offset as a fourth coordinate.
double metricDistance(const Vec3& d, const CrackleSettings& s) {
    if (s.metric == 2) return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z + s.offset * s.offset);
    if (s.metric == 1) return std::abs(d.x) + std::abs(d.y) + std::abs(d.z) + std::abs(s.offset);
    const double m = s.metric;
    return std::pow(std::pow(std::abs(d.x), m) + std::pow(std::abs(d.y), m) +
                        std::pow(std::abs(d.z), m) + std::pow(std::abs(s.offset), m),
                    1.0 / m);
}

}  // namespace

double crackle(const Vec3& p, const CrackleSettings& s, NoiseGenerator generator) {
    const int cx = latticeFloor(p.x);
    const int cy = latticeFloor(p.y);
    const int cz = latticeFloor(p.z);
    // The three smallest distances over the 27 cells around p (enough to
    // reproduce povray for metrics 1 to 3: measured).
    double d[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
    Vec3 nearest{};
    for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dz = -1; dz <= 1; ++dz) {
                const Vec3 f = crackleFeaturePoint(cx + dx, cy + dy, cz + dz);
                const double dist = metricDistance(p - f, s);
                if (dist < d[0]) {
                    d[2] = d[1];
                    d[1] = d[0];
                    d[0] = dist;
                    nearest = f;
                } else if (dist < d[1]) {
                    d[2] = d[1];
                    d[1] = dist;
                } else if (dist < d[2]) {
                    d[2] = dist;
                }
            }
    if (s.solid) return solidNoise(nearest, generator);
    const double v = s.form.x * d[0] + s.form.y * d[1] + s.form.z * d[2];
    return std::clamp(v, 0.0, 1.0);  // povray clamps (measured with negative forms)
}

}  // namespace frameray::scene
