#include "scene/facets.h"

#include <cmath>

#include "scene/crackle.h"
#include "util/lattice_hash.h"

namespace frameray::scene {

namespace {

double metricSum(const Vec3& d, double metric) {
    if (metric == 2) return dot(d, d);
    // povray sums the signed differences for metric 1 (measured).
    if (metric == 1) return d.x + d.y + d.z;
    return std::pow(std::abs(d.x), metric) + std::pow(std::abs(d.y), metric) +
           std::pow(std::abs(d.z), metric);
}

}  // namespace

Vec3 facetsNormal(const Vec3& p, const Vec3& n, const FacetsSettings& s, double metric) {
    const double scale = s.size < 1e-6 ? 1e6 : 1.0 / s.size;
    const Vec3 t = (s.coords != 0 ? p : n) * scale;
    const int cx = latticeFloor(t.x);
    const int cy = latticeFloor(t.y);
    const int cz = latticeFloor(t.z);
    // The nearest feature point lies within a knight's move: cells up to
    // two away along at most one axis and one away along the others.
    double best = 300000.0;
    Vec3 nearest = t;
    for (int dx = -2; dx <= 2; ++dx)
        for (int dy = -2; dy <= 2; ++dy)
            for (int dz = -2; dz <= 2; ++dz) {
                if ((std::abs(dx) == 2) + (std::abs(dy) == 2) + (std::abs(dz) == 2) > 1) continue;
                const Vec3 f = crackleFeaturePoint(cx + dx, cy + dy, cz + dz);
                const double d = metricSum(f - t, metric);
                if (d < best) {
                    best = d;
                    nearest = f;
                }
            }
    if (s.coords == 0) return nearest;
    Vec3 pert = vectorNoise(nearest);
    pert -= n * dot(pert, n);
    return n + pert * s.coords;
}

}  // namespace frameray::scene
