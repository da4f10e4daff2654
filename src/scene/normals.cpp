#include "scene/normals.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace frameray::scene {

namespace {

// The four directions of povray's sampling tetrahedron.
constexpr Vec3 kTetrahedron[4] = {{0.942809041, -0.333333333, 0.0},
                                  {-0.471404521, -0.333333333, 0.816496581},
                                  {-0.471404521, -0.333333333, -0.816496581},
                                  {0.0, 1.0, 0.0}};

bool isNormalPattern(PatternKind k) {
    return k == PatternKind::Bumps || k == PatternKind::Dents || k == PatternKind::Wrinkles ||
           k == PatternKind::Ripples || k == PatternKind::Waves || k == PatternKind::Quilted ||
           k == PatternKind::Facets;
}

// Normals go into pattern space with the transpose of each transformation
// (points go with the inverse), walking the chain like points do.
Vec3 normalToPattern(const Pattern& pattern, Vec3 n) {
    for (auto it = pattern.chain.rbegin(); it != pattern.chain.rend(); ++it)
        if (it->kind == Warp::Kind::Transform) n = it->transform.inverse().normal(n);
    return n;
}

Vec3 normalFromPattern(const Pattern& pattern, Vec3 n) {
    for (const Warp& w : pattern.chain)
        if (w.kind == Warp::Kind::Transform) n = w.transform.normal(n);
    return n;
}

double cycloidal(double v) {
    return std::sin(v * 2.0 * std::numbers::pi);
}

// The vector a built-in normal pattern adds at pattern-space point q to the
// unit pattern-space normal m.
Vec3 normalPatternVector(const Normal& nm, const Vec3& q, const Vec3& m) {
    const Pattern& pat = nm.pattern;
    switch (pat.kind) {
        case PatternKind::Bumps:
            return vectorNoise(q) * nm.amount;
        case PatternKind::Dents: {
            const double s = solidNoise(q, pat.noiseGenerator);
            return vectorNoise(q) * (s * s * s * nm.amount);
        }
        case PatternKind::Wrinkles: {
            Vec3 sum;
            double scale = 1.0;
            for (int i = 0; i < 10; ++i, scale *= 2.0) {
                const Vec3 d = vectorNoise(q * scale);
                sum += Vec3(std::abs(d.x / scale), std::abs(d.y / scale), std::abs(d.z / scale));
            }
            return sum * nm.amount;
        }
        case PatternKind::Ripples:
        case PatternKind::Waves: {
            const bool waves = pat.kind == PatternKind::Waves;
            const WaveSources& w = pat.waveSources();
            const double n = static_cast<double>(w.center.size());
            Vec3 sum;
            for (std::size_t i = 0; i < w.center.size(); ++i) {
                const Vec3 d = q - w.center[i];
                double len = length(d);
                if (len == 0) len = 1;
                const double f = waves ? w.frequency[i] : 1.0;
                const double s = cycloidal(len * pat.frequency * f + pat.phase) * nm.amount;
                sum += d * (s / (len * n * (waves ? f : 1.0)));
            }
            return sum;
        }
        case PatternKind::Quilted:
            // povray's quilted normal adds the quilt offset itself rather
            // than sampling the pattern's slope, scaled by the pattern's
            // 2/sqrt(3) (measured: the tilt of a plane under lights along
            // the axes fits 1.1547 times the offset, not 1.0).
            return quiltOffset(q, pat.control0, pat.control1) * (nm.amount * 1.154700538);
        case PatternKind::Facets:
            return facetsNormal(q, m, pat.facets, pat.crackle.metric) - m;
        default:
            return {};
    }
}

// The pattern's value at pattern-space point q for the sampling
// tetrahedron: a list pattern (checker, object, ...) gives its index, through
// the wave only when frequency, phase or the wave type are set (as in
// pattern functions), so the normal tilts only along the cells' edges.
double sampleValue(const Pattern& pat, const Vec3& q, const SurfaceInfo* surface) {
    if (!pat.isList()) return pat.wave(pat.raw(q, surface));
    const double index = pat.indexAt(q);
    const bool plain = pat.frequency == 1 && pat.phase == 0 && pat.waveType == WaveType::Ramp;
    return plain ? index : pat.wave(index);
}

}  // namespace

Vec3 mapEntryPoint(const Pattern& pattern, const Vec3& p) {
    // Agate's `turbulence` displaces the point as a warp (patternPoint).
    const bool ownTurbulence =
        pattern.kind == PatternKind::Marble || pattern.kind == PatternKind::Wood;
    bool warped = pattern.turbulence.has_value() && !ownTurbulence;
    for (const Warp& w : pattern.chain) warped = warped || w.kind != Warp::Kind::Transform;
    if (!warped) return p;
    Vec3 q = pattern.patternPoint(p);
    for (const Warp& w : pattern.chain)
        if (w.kind == Warp::Kind::Transform) q = w.transform.point(q);
    return q;
}

void Normal::transformBy(const Transform& t) {
    pattern.addTransform(t);
    for (auto& e : map) {
        if (!e.normal) continue;
        auto moved = std::make_shared<Normal>(*e.normal);
        moved->transformBy(t);
        e.normal = std::move(moved);
    }
}

double Normal::slopeHeight(double v) const {
    if (slopeMap.empty()) return v;
    if (v <= slopeMap.front().value) return slopeMap.front().height;
    std::size_t hi = 1;
    while (hi < slopeMap.size() && slopeMap[hi].value <= v) ++hi;
    if (hi == slopeMap.size()) return slopeMap.back().height;
    const SlopeEntry& a = slopeMap[hi - 1];
    const SlopeEntry& b = slopeMap[hi];
    const double span = b.value - a.value;
    if (span <= 0) return b.height;
    // Cubic Hermite between the two entries on the interval's own
    // parameter t in [0, 1]: the slopes are not scaled by the interval's
    // width (povray's slope_map).
    const double t = (v - a.value) / span, t2 = t * t, t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * a.height + (t3 - 2 * t2 + t) * a.slope +
           (-2 * t3 + 3 * t2) * b.height + (t3 - t2) * b.slope;
}

Vec3 Normal::perturb(const Vec3& p, const Vec3& n, const SurfaceInfo* surface) const {
    const Vec3 m = perturbUnnormalized(p, n, surface);
    const double len = length(m);
    return len > 0 ? m * (1.0 / len) : n;
}

Vec3 Normal::perturbUnnormalized(const Vec3& p, const Vec3& n, const SurfaceInfo* surface) const {
    if (mapMode != MapMode::None && !map.empty()) {
        // The picked normals perturb the surface on their own, at the point
        // the map's warps displaced; their unit normals are blended by
        // weight (measured: blending the unnormalised ones does not match).
        const Vec3 entry = mapEntryPoint(pattern, p);
        Vec3 sum;
        auto add = [&](const MapEntry& e, double w) {
            sum += (e.normal ? e.normal->perturb(entry, n, surface) : n) * w;
        };
        switch (mapMode) {
            case MapMode::List: {
                const auto i = static_cast<std::size_t>(std::max(0, pattern.index(p)));
                add(map[std::min(i, map.size() - 1)], 1.0);
                break;
            }
            case MapMode::Average: {
                double total = 0;
                for (const MapEntry& e : map) total += e.value;
                if (total == 0) return n;
                for (const MapEntry& e : map) add(e, e.value / total);
                break;
            }
            default: {
                const double v = pattern.value(p, surface);
                std::size_t hi = 0;
                while (hi < map.size() && map[hi].value <= v) ++hi;
                if (hi == 0) {
                    add(map.front(), 1.0);
                } else if (hi == map.size()) {
                    add(map.back(), 1.0);
                } else {
                    const MapEntry& a = map[hi - 1];
                    const MapEntry& b = map[hi];
                    const double span = b.value - a.value;
                    const double t = span > 0 ? (v - a.value) / span : 1.0;
                    add(a, 1.0 - t);
                    add(b, t);
                }
                break;
            }
        }
        return sum;
    }
    Vec3 m = normalize(normalToPattern(pattern, n));
    if (bumpMap) {
        m = bumpMapNormal(*bumpMap, amount, pattern.patternPoint(p), m);
    } else if (isNormalPattern(pattern.kind)) {
        // The normal patterns make their own vectors and ignore a slope_map.
        m += normalPatternVector(*this, pattern.patternPoint(p), m);
    } else {
        // povray's fudge factor: -5 times the bump size per sample, as a
        // slope relative to the default accuracy of 0.02 (measured).
        const double weight = -5.0 * amount * (0.02 / accuracy);
        const Vec3 q = pattern.patternPoint(p);
        for (const Vec3& dir : kTetrahedron)
            m += dir * (slopeHeight(sampleValue(pattern, q + dir * accuracy, surface)) * weight);
    }
    return normalFromPattern(pattern, m);
}

}  // namespace frameray::scene
