#include "render/radiosity.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace frameray::render {

namespace {

// A cosine-weighted set of n directions around +z: a spiral lattice over
// the unit disc (point k at radius sqrt((k + 1/2) / n), turned by the
// golden angle each step: evenly spread for any n), lifted to the
// hemisphere (Malley's method: uniform over the disc is cosine-weighted
// over the hemisphere). The same set serves every sample; samples differ
// in the frame it is turned into.
std::vector<Vec3> spiralDirections(int n) {
    std::vector<Vec3> out;
    out.reserve(static_cast<size_t>(n));
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (int k = 0; k < n; ++k) {
        const double r2 = (k + 0.5) / n;
        const double r = std::sqrt(r2);
        const double phi = golden * k;
        out.emplace_back(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - r2)));
    }
    return out;
}

}  // namespace

Radiosity::Radiosity(const scene::RadiositySettings& settings, const Vec3& eye, bool legacyAmbient)
    : settings_(settings),
      eye_(eye),
      legacyAmbient_(legacyAmbient),
      reachFactor_(settings.errorBound * std::max(1.0, settings.lowErrorFactor)) {
    for (int depth = 0; depth < settings.recursionLimit; ++depth)
        directions_.push_back(spiralDirections(std::max(1, settings.count >> std::min(depth, 30))));
}

std::span<const Vec3> Radiosity::directions(int count, std::vector<Vec3>& scratch) const {
    for (const std::vector<Vec3>& set : directions_)
        if (static_cast<int>(set.size()) == count) return set;
    scratch = spiralDirections(count);
    return scratch;
}

void Radiosity::add(const RadiositySample& sample) {
    octree_.insert(static_cast<std::uint32_t>(samples_.size()), sample.point,
                   sample.radius * reachFactor_);
    samples_.push_back(sample);
}

namespace {

// The best samples found for one lookup, by increasing error.
struct Candidates {
    static constexpr int kMax = 20;  // nearest_count's limit
    std::array<double, kMax> error{};
    std::array<const RadiositySample*, kMax> sample{};
    int size = 0;
    int limit = 0;

    void offer(double e, const RadiositySample* s) {
        if (size == limit && e >= error[static_cast<size_t>(size - 1)]) return;
        int i = size < limit ? size++ : size - 1;
        while (i > 0 && error[static_cast<size_t>(i - 1)] > e) {
            error[static_cast<size_t>(i)] = error[static_cast<size_t>(i - 1)];
            sample[static_cast<size_t>(i)] = sample[static_cast<size_t>(i - 1)];
            --i;
        }
        error[static_cast<size_t>(i)] = e;
        sample[static_cast<size_t>(i)] = s;
    }
};

// The error of reusing sample s at p (normal n), Ward's measure: the
// distance in units of the sample's radius plus the normals' divergence;
// negative when s may not be used at all.
double reuseError(const RadiositySample& s, const Vec3& p, const Vec3& n) {
    const double cosNormals = dot(n, s.normal);
    if (cosNormals <= 0) return -1;
    const Vec3 d = p - s.point;
    // A sample in front of p (p lies behind its surface) sees light p
    // does not.
    if (dot(d, n + s.normal) < -0.1 * s.radius) return -1;
    return length(d) / s.radius + std::sqrt(std::max(0.0, 1.0 - cosNormals));
}

}  // namespace

RadiosityTask::Lookup RadiosityTask::interpolate(const Vec3& p, const Vec3& n, int depth) const {
    const scene::RadiositySettings& set = radiosity_.settings();
    const double bound = set.errorBound * (pretrace_ ? set.lowErrorFactor : 1.0);
    Candidates best;
    best.limit = set.nearestCount;
    auto consider = [&](const RadiositySample& s) {
        // Only samples gathered as deep: a shallower one holds more
        // bounces, a deeper one fewer, than this lookup may see (measured:
        // a room at recursion_limit 2 and 3 matches povray exactly so,
        // and is a level too bright when shallower samples are reused).
        if (s.depth != depth) return;
        const double e = reuseError(s, p, n);
        if (e >= 0 && e < bound) best.offer(e, &s);
    };
    const std::vector<RadiositySample>& shared = radiosity_.samples();
    radiosity_.octree().query(p, [&](std::uint32_t i) { consider(shared[i]); });
    for (const RadiositySample& s : own_) consider(s);
    Lookup out;
    out.found = best.size;
    if (best.size == 0) return out;
    RGB sum(0.0);
    double weights = 0;
    for (int i = 0; i < best.size; ++i) {
        // Weights fall smoothly to 0 at the error bound.
        const double e = best.error[static_cast<size_t>(i)];
        const double w = (1.0 - e / bound) * (1.0 - e / bound);
        sum += best.sample[static_cast<size_t>(i)]->irradiance * w;
        weights += w;
    }
    out.irradiance = sum * (1.0 / weights);
    return out;
}

bool RadiosityTask::wantsSample(int found, int depth) const {
    const scene::RadiositySettings& set = radiosity_.settings();
    if (depth > 0) return found == 0;
    // Measured (povray's sample counts per pass as nearest_count varies):
    // pretrace passes gather until nearest_count samples are near enough;
    // the final pass only where none is, unless always_sample.
    if (pretrace_ || set.alwaysSample) return found < set.nearestCount;
    return found == 0;
}

void RadiosityTask::add(const RadiositySample& sample) {
    ++counts.samples;
    if (sample.depth > 0) ++counts.deeper;
    if (writeShared_)
        radiosity_.add(sample);
    else
        own_.push_back(sample);
}

}  // namespace frameray::render
