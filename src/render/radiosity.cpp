#include "render/radiosity.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace frameray::render {

namespace {

// povray's cache coordinates are shifted by this much, so that every cell
// index is positive.
constexpr double kCellBias = 10000000.0;

// The largest power of two not above x (as a single-precision float
// rounds it), 1 for 0.
double floorPow2(double x) {
    const float f = static_cast<float>(x);
    if (!(f > 0)) return 1.0;
    int e = 0;
    std::frexp(f, &e);
    return std::ldexp(1.0, e - 1);
}

}  // namespace

bool RadiosityCell::sees(const Vec3& p) const {
    return std::fabs(p.x + kCellBias - cx) < size && std::fabs(p.y + kCellBias - cy) < size &&
           std::fabs(p.z + kCellBias - cz) < size;
}

Radiosity::Radiosity(const scene::RadiositySettings& settings, const Vec3& eye, bool legacyAmbient)
    : settings_(settings),
      eye_(eye),
      legacyAmbient_(legacyAmbient),
      poolSize_(static_cast<size_t>(std::max({1, settings.directionPool, settings.count}))) {
    for (int d = 0; d < std::max(1, settings.recursionLimit); ++d) {
        RadiosityDepth depth;
        const double scale = std::ldexp(1.0, d);
        depth.rays = std::max(5, static_cast<int>(settings.count / scale));
        depth.reuseWeight =
            d == 0 ? settings.nearestCount : (d == 1 ? std::min(2, settings.nearestCount) : 1);
        depth.boundFactor = scale;
        depth.minimumReuse = settings.minimumReuse * scale;
        depth.maximumReuse = settings.maximumReuse * scale;
        depth.cellFactor = settings.errorBound * scale / (d == 0 ? 1.0 : 8.0);
        depths_.push_back(depth);
    }
}

namespace {

// The radical inverse of n in base b (the digits of n mirrored about the
// point): point n of the van der Corput sequence.
double radicalInverse(size_t n, size_t base) {
    double result = 0;
    const double inverse = 1.0 / static_cast<double>(base);
    double digit = inverse;
    for (; n > 0; n /= base, digit *= inverse) result += static_cast<double>(n % base) * digit;
    return result;
}

}  // namespace

Vec3 Radiosity::direction(size_t index) {
    const double r2 = radicalInverse(index + 1, 2);
    const double phi = 2 * std::numbers::pi * radicalInverse(index + 1, 3);
    const double r = std::sqrt(r2);
    return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - r2))};
}

void Radiosity::sampleFrame(const Vec3& n, Vec3& u, Vec3& v, Vec3& w) {
    constexpr double kNearY = 0.001;
    if (n.y > 1 - kNearY || n.y < -1 + kNearY) {
        const double s = n.y > 0 ? 1.0 : -1.0;
        u = Vec3(s, 0, 0);
        v = Vec3(0, 0, s);
        w = Vec3(0, s, 0);
        return;
    }
    const Vec3 axis = std::fabs(n.z) >= 0.9 ? Vec3(0, 1, 0) : Vec3(0, 0, 1);
    u = normalize(cross(n, axis));
    v = cross(u, n);
    w = n;
}

RadiosityCell Radiosity::cellOf(const RadiositySample& sample) const {
    const double reach = sample.radius * depth(sample.depth).cellFactor;
    double size = floorPow2(2 * reach);
    const Vec3& c = sample.point;
    const double farthest =
        std::max({std::fabs(c.x - reach), std::fabs(c.y - reach), std::fabs(c.z - reach)}) +
        kCellBias;
    while (farthest / size > 1e9) size *= 2;
    double ix = std::floor((c.x + kCellBias) / size);
    double iy = std::floor((c.y + kCellBias) / size);
    double iz = std::floor((c.z + kCellBias) / size);
    auto holds = [&](const Vec3& p) {
        return std::fabs(p.x + kCellBias - (ix + 0.5) * size) < size &&
               std::fabs(p.y + kCellBias - (iy + 0.5) * size) < size &&
               std::fabs(p.z + kCellBias - (iz + 0.5) * size) < size;
    };
    while (!holds(c - Vec3(reach)) || !holds(c + Vec3(reach))) {
        ix = std::floor(ix * 0.5);
        iy = std::floor(iy * 0.5);
        iz = std::floor(iz * 0.5);
        size *= 2;
    }
    return {size, (ix + 0.5) * size, (iy + 0.5) * size, (iz + 0.5) * size};
}

void Radiosity::add(const RadiositySample& sample) {
    const RadiosityCell cell = cellOf(sample);
    // The cell widened by half its size holds every point that sees the
    // sample.
    octree_.insert(static_cast<std::uint32_t>(samples_.size()), sample.point, 1.5 * cell.size);
    samples_.push_back(sample);
    cells_.push_back(cell);
}

namespace {

// How much sample s counts at p (normal n) for a lookup with error bound
// `bound`; 0 when it may not be used. povray 3.7's rules: the error is
// the distance in units of the sample's reuse radius (shrunk toward the
// nearest surface its rays met, in that direction) plus twice the root of
// the normals' divergence; the weight falls from 1 to 0 at the bound,
// smoothly for the final pass's top-level lookups and linearly otherwise;
// a sample in front of p (p behind its surface) fades out over a short
// distance.
double reuseWeight(const RadiositySample& s, const Vec3& p, const Vec3& n, double bound,
                   bool smooth) {
    const Vec3 d = p - s.point;
    const double dist2 = dot(d, d);
    const double quick = s.radius * bound;
    if (dist2 >= quick * quick) return 0;
    const double dist = std::sqrt(dist2);
    double ri = s.radius;
    const bool apart = dist > 1e-6;
    Vec3 unit;
    if (apart) {
        unit = d * (1.0 / dist);
        const double towardNearest = dot(s.toNearest, unit);
        if (s.nearest > 0 && towardNearest > 0)
            ri = towardNearest * s.nearest + (1 - towardNearest) * ri;
    }
    if (dist >= ri * bound) return 0;
    const double error = dist / ri + 2 * std::sqrt(std::fabs(1 - dot(n, s.normal)));
    if (error >= bound) return 0;
    double inFront = 1;
    constexpr double kInFrontLimit = -0.05;
    if (apart) {
        const Vec3 half = n + s.normal;
        inFront = dot(unit, half) / length(half);
    }
    if (!(inFront > kInFrontLimit)) return 0;
    const double t = error / bound;
    double w;
    if (smooth)
        w = t < 0.5 ? 1 - 2 * t * t : 2 * (1 - t) * (1 - t);
    else
        w = 1 - t;
    if (inFront <= 0) w *= 1 - inFront / kInFrontLimit;
    return w > 0.001 ? w : 0;
}

}  // namespace

RadiosityTask::Lookup RadiosityTask::interpolate(const Vec3& p, const Vec3& n, int depth,
                                                 double weight) const {
    const scene::RadiositySettings& set = radiosity_.settings();
    double bound = set.errorBound * (pretrace_ ? set.lowErrorFactor : 1.0);
    if (weight < 0.25) bound += 0.25 - weight;
    bound *= radiosity_.depth(depth).boundFactor;
    const bool smooth = !pretrace_ && depth == 0;
    if (lookups_.empty) {
        lookups_ = {p, p, false};
    } else {
        lookups_.lo = Vec3(std::min(lookups_.lo.x, p.x), std::min(lookups_.lo.y, p.y),
                           std::min(lookups_.lo.z, p.z));
        lookups_.hi = Vec3(std::max(lookups_.hi.x, p.x), std::max(lookups_.hi.y, p.y),
                           std::max(lookups_.hi.z, p.z));
    }
    Lookup out;
    RGB sum(0.0);
    auto consider = [&](const RadiositySample& s, const RadiosityCell& cell) {
        if (s.depth != depth) return;
        if (s.pass == pass_ && s.tile != tile_) return;
        if (!cell.sees(p)) return;
        const double w = reuseWeight(s, p, n, bound, smooth) * s.quality;
        if (w <= 0) return;
        sum += s.irradiance * w;
        out.weight += w;
        ++out.found;
    };
    const std::vector<RadiositySample>& shared = radiosity_.samples();
    const std::vector<RadiosityCell>& cells = radiosity_.cells();
    radiosity_.octree().query(p, [&](std::uint32_t i) { consider(shared[i], cells[i]); });
    for (size_t i = 0; i < own_.size(); ++i) consider(own_[i], ownCells_[i]);
    if (out.weight > 0) out.irradiance = sum * (1.0 / out.weight);
    return out;
}

bool RadiosityTask::wantsSample(const Lookup& found, int depth) const {
    const scene::RadiositySettings& set = radiosity_.settings();
    // povray 3.7: a lookup reuses when the weights it found add up to a
    // quarter of nearest_count (2 one bounce deep, 1 deeper); the final
    // pass reuses any weight unless always_sample.
    if (found.weight * 4 >= radiosity_.depth(depth).reuseWeight) return false;
    if (!pretrace_ && !set.alwaysSample && found.weight > 0) return false;
    return true;
}

size_t RadiosityTask::takeDirections(int depth, size_t count) {
    if (cursor_.size() <= static_cast<size_t>(depth))
        cursor_.resize(static_cast<size_t>(depth) + 1);
    gathered_ = true;
    const size_t start = cursor_[static_cast<size_t>(depth)];
    cursor_[static_cast<size_t>(depth)] = (start + count) % radiosity_.poolSize();
    return start;
}

void RadiosityTask::add(RadiositySample sample) {
    ++counts.samples;
    if (sample.depth > 0) ++counts.deeper;
    sample.pass = pretrace_ ? pass_ : 0;
    sample.tile = tile_;
    if (writeShared_) {
        radiosity_.add(sample);
    } else {
        ownCells_.push_back(radiosity_.cellOf(sample));
        own_.push_back(sample);
    }
}

}  // namespace frameray::render
