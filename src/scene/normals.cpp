#include "scene/normals.h"

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
           k == PatternKind::Ripples || k == PatternKind::Waves;
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

// The vector a built-in normal pattern adds at pattern-space point q.
Vec3 normalPatternVector(const Normal& nm, const Vec3& q) {
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
            Vec3 sum;
            for (int i = 0; i < kWaveSourceCount; ++i) {
                const Vec3 d = q - waveSourceCenter(i);
                double len = length(d);
                if (len == 0) len = 1;
                const double f = waves ? waveSourceFrequency(i) : 1.0;
                const double s = cycloidal(len * pat.frequency * f + pat.phase) * nm.amount;
                sum += d * (s / (len * kWaveSourceCount * (waves ? f : 1.0)));
            }
            return sum;
        }
        default:
            return {};
    }
}

}  // namespace

Vec3 Normal::perturb(const Vec3& p, const Vec3& n) const {
    Vec3 m = normalize(normalToPattern(pattern, n));
    if (bumpMap) {
        m = bumpMapNormal(*bumpMap, amount, pattern.patternPoint(p), m);
    } else if (isNormalPattern(pattern.kind)) {
        m += normalPatternVector(*this, pattern.patternPoint(p));
    } else {
        // povray's fudge factor: -5 times the bump size per sample, as a
        // slope relative to the default accuracy of 0.02 (measured).
        const double weight = -5.0 * amount * (0.02 / accuracy);
        const Vec3 q = pattern.patternPoint(p);
        for (const Vec3& dir : kTetrahedron)
            m += dir * (pattern.wave(pattern.raw(q + dir * accuracy)) * weight);
    }
    return normalize(normalFromPattern(pattern, m));
}

}  // namespace frameray::scene
